package glint.accel;

import glint.geometry.Hit;
import glint.geometry.PrimitiveKind;
import java.util.Arrays;

/**
 * A filter that answers some rays from cube maps of direction cells ({@link CellMaps}): such a ray
 * tests the unbounded primitives and its cell's list instead of searching. The shape of
 * {@link LeavingCells} (rays leaving a closed primitive) and {@link LightCells} (shadow rays
 * towards a point light).
 */
abstract class CellFilter extends AggregateFilter {

    private static final int COUNT_MASK = (1 << CellMaps.COUNT_BITS) - 1;

    /** Cells along a cube face's side. */
    private final int k;
    /** Per cell, its listing ({@link CellMaps#cell}): first slot and count, or -1: fall back. */
    final int[] cell;
    /**
     * The cells' lists of primitive numbers, and per slot the primitive's kind and index within it.
     * Tested here rather than by {@link PrimitiveSlots} (whose call of the kind the hierarchy's
     * leaves and the planes share): through it the lists took 1.06, 1.02 and 1.02 of the default
     * scene's, glass-25's and field-1000's render CPU a frame, tested here 1.00, 0.99 and 1.00
     * (against the loops before PrimitiveSlots; CompareBuilds, 1 thread, 16 pairs, 2026-12-02).
     */
    private final int[] listed, listedIndex;
    private final PrimitiveKind[] listedKind;
    private final PrimitiveSlots unbounded;

    CellFilter(Aggregate searched, CellMaps maps) {
        super(searched);
        this.k = maps.k;
        this.cell = Arrays.copyOf(maps.cell, maps.cells);
        this.listed = Arrays.copyOf(maps.listed, maps.slots);
        this.listedKind = primitives.kindsOf(listed);
        this.listedIndex = primitives.indicesOf(listed);
        this.unbounded = new PrimitiveSlots(primitives, primitives.unbounded());
    }

    /**
     * The nearest hit among the unbounded primitives (but skip) and the list of a cell's
     * {@code listing}, in that fixed order, as the hierarchy tests them.
     */
    final boolean nearestListed(double ox, double oy, double oz, double dx, double dy, double dz, double tMax,
                                int skip, int listing, Hit hit) {
        double nearest = unbounded.nearest(0, unbounded.count(), ox, oy, oz, dx, dy, dz, tMax, skip, hit);
        int found = Hit.NONE;
        for (int slot = listing >>> CellMaps.COUNT_BITS, end = slot + (listing & COUNT_MASK); slot < end; slot++) {
            double t = listedKind[slot].intersect(listedIndex[slot], ox, oy, oz, dx, dy, dz, nearest);
            if (t < nearest) {
                nearest = t;
                found = listed[slot];
            }
        }
        if (found != Hit.NONE) {
            primitives.record(hit, found, nearest);
        }
        return nearest < tMax;
    }

    /**
     * The light passed along the ray through the unbounded primitives and the list of a cell's
     * {@code listing} (but skip): the product of {@code pass} over those it meets before tMax, 0
     * as soon as one passes nothing.
     */
    final double transmittanceListed(double ox, double oy, double oz, double dx, double dy, double dz, double tMax,
                                     int skip, int listing, double[] pass) {
        double passed = unbounded.transmittance(0, unbounded.count(), ox, oy, oz, dx, dy, dz, tMax, skip, pass, 1);
        if (passed == 0) {
            return 0;
        }
        for (int slot = listing >>> CellMaps.COUNT_BITS, end = slot + (listing & COUNT_MASK); slot < end; slot++) {
            int q = listed[slot];
            if (q != skip && listedKind[slot].intersect(listedIndex[slot], ox, oy, oz, dx, dy, dz, tMax) < tMax) {
                passed *= pass[q];
                if (passed == 0) {
                    return 0;
                }
            }
        }
        return passed;
    }

    /**
     * The cell of a direction within a map: the face of its largest component (+x, -x, +y, -y, +z,
     * -z), then the other two components over the largest one's size, each in [-1, 1], cut into k
     * steps.
     */
    final int cellOf(double dx, double dy, double dz) {
        double ax = Math.abs(dx), ay = Math.abs(dy), az = Math.abs(dz);
        int face;
        double major, u, v;
        if (ax >= ay && ax >= az) {
            face = dx > 0 ? 0 : 1;
            major = ax;
            u = dy;
            v = dz;
        } else if (ay >= az) {
            face = dy > 0 ? 2 : 3;
            major = ay;
            u = dx;
            v = dz;
        } else {
            face = dz > 0 ? 4 : 5;
            major = az;
            u = dx;
            v = dy;
        }
        int k = this.k;
        double scale = 0.5 * k / major;
        int i = Math.min(k - 1, Math.max(0, (int) (u * scale + 0.5 * k)));
        int j = Math.min(k - 1, Math.max(0, (int) (v * scale + 0.5 * k)));
        return (face * k + i) * k + j;
    }

    /** How many cells fall back, and how many primitives the cells list in all. */
    final String cellCounts() {
        long fallBack = Arrays.stream(cell).filter(listing -> listing < 0).count();
        return fallBack + " of " + cell.length + " cells fall back, " + listed.length + " listed";
    }
}
