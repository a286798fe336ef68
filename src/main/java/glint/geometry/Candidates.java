package glint.geometry;

/**
 * Scratch value: the primitives a set of rays may meet, gathered once by
 * {@link Aggregate#gather} (say for a row of camera rays) and then searched ray by ray. Searching
 * them finds the same hit as the aggregate does for every ray of the set.
 */
public final class Candidates {

    private int[] primitives = new int[16];
    private int count;
    /** A box's scratch, for the aggregates that gather into it. */
    final double[] box = new double[6];

    /** How many were gathered. */
    public int count() {
        return count;
    }

    void clear() {
        count = 0;
    }

    void add(int primitive) {
        if (count == primitives.length) {
            primitives = java.util.Arrays.copyOf(primitives, 2 * count);
        }
        primitives[count++] = primitive;
    }

    /**
     * The nearest hit among the gathered primitives with t in (0, tMax), into {@code hit}, as
     * {@link Aggregate#nearest} gives it for a ray of the set the primitives were gathered for.
     */
    public boolean nearest(Primitives p, double ox, double oy, double oz, double dx, double dy, double dz,
                           double tMax, Hit hit) {
        double nearest = tMax;
        int found = Hit.NONE;
        for (int i = 0; i < count; i++) {
            int q = primitives[i];
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
}
