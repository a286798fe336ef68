package glint.accel;

import glint.geometry.Primitives;
import glint.geometry.Hit;

/** Every ray tests every primitive: the brute force the renderer's aggregates are checked against. */
public final class FlatList implements Aggregate {

    private final Primitives primitives;

    public FlatList(Primitives primitives) {
        this.primitives = primitives;
    }

    @Override
    public boolean nearest(double ox, double oy, double oz, double dx, double dy, double dz, double tMax, int skip,
                           int inside, Hit hit, TraversalStack stack) {
        Primitives p = primitives;
        double nearest = tMax;
        int found = Hit.NONE;
        for (int q = 0; q < p.count(); q++) {
            if (q == skip) {
                continue;
            }
            double t = p.intersect(q, ox, oy, oz, dx, dy, dz, nearest);
            if (t < nearest) {
                nearest = t;
                found = q;
            }
        }
        if (found == Hit.NONE) {
            return false;
        }
        p.record(hit, found, nearest);
        return true;
    }

    @Override
    public double transmittance(double ox, double oy, double oz, double dx, double dy, double dz, double tMax,
                                int skip, double[] pass, TraversalStack stack) {
        Primitives p = primitives;
        double passed = 1;
        for (int q = 0; q < p.count(); q++) {
            if (q != skip && p.intersect(q, ox, oy, oz, dx, dy, dz, tMax) < tMax) {
                passed *= pass[q];
                if (passed == 0) {
                    return 0;
                }
            }
        }
        return passed;
    }

    @Override
    public void gather(Frustum frustum, Candidates out, TraversalStack stack) {
        out.clear();
        double[] box = new double[6];
        for (int q = 0; q < primitives.count(); q++) {
            if (!primitives.bounded(q)) {
                out.add(q);
                continue;
            }
            primitives.bounds(q, box, 0);
            if (frustum.mayHold(box, 0)) {
                out.add(q);
            }
        }
    }

    @Override
    public Primitives primitives() {
        return primitives;
    }

    @Override
    public TraversalStack newStack() {
        return new TraversalStack(0);
    }
}
