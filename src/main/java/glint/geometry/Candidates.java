package glint.geometry;

import java.util.Arrays;

/**
 * Scratch value: the primitives a set of rays may meet, gathered once by
 * {@link Aggregate#gather} (say for a row of camera rays) and then searched for all the rays at
 * once, primitive by primitive. Searching them finds the same hit as the aggregate does for every
 * ray of the set.
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
            primitives = Arrays.copyOf(primitives, 2 * count);
        }
        primitives[count++] = primitive;
    }

    /**
     * The nearest hits among the gathered primitives of the rays r in [0, n) from the common
     * origin o along (dx[r], dy[r], dz[r]): nearestT[r] and nearestPrimitive[r] become the distance
     * and number of each ray's nearest hit, or {@link Intersect#MISS} and {@link Hit#NONE}; where two
     * are met at the same distance, the one gathered first.
     */
    public void nearestFromOrigin(Primitives p, double ox, double oy, double oz, double[] dx, double[] dy,
                                  double[] dz, int n, double[] nearestT, int[] nearestPrimitive) {
        Arrays.fill(nearestT, 0, n, Intersect.MISS);
        Arrays.fill(nearestPrimitive, 0, n, Hit.NONE);
        for (int i = 0; i < count; i++) {
            p.nearestFromOrigin(primitives[i], ox, oy, oz, dx, dy, dz, n, nearestT, nearestPrimitive);
        }
    }
}
