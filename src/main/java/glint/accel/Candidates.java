package glint.accel;

import glint.geometry.Primitives;
import glint.geometry.Intersect;
import glint.geometry.Hit;
import java.util.Arrays;

/**
 * Scratch value: the primitives a set of rays may meet, gathered once by
 * {@link Aggregate#gather} (say for a row of camera rays) and then searched for all the rays at
 * once, primitive by primitive. Searching them finds the same hit as the aggregate does for every
 * ray of the set. A caller that knows a primitive can meet only some of the rays (a row's rays
 * ordered across the screen, a primitive covering part of it) may narrow its rays to a range
 * ({@link #narrow}).
 */
public final class Candidates {

    private int[] primitives = new int[16];
    /** Per gathered primitive: the rays [firstRay, endRay) it is searched for. */
    private int[] firstRay = new int[16], endRay = new int[16];
    private int count;

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
            firstRay = Arrays.copyOf(firstRay, 2 * count);
            endRay = Arrays.copyOf(endRay, 2 * count);
        }
        firstRay[count] = 0;
        endRay[count] = Integer.MAX_VALUE;
        primitives[count++] = primitive;
    }

    /** The number of the i-th primitive gathered. */
    public int primitive(int i) {
        return primitives[i];
    }

    /** Whether the i-th primitive gathered is searched for ray r. */
    public boolean searches(int i, int r) {
        return firstRay[i] <= r && r < endRay[i];
    }

    /** Searches the i-th primitive gathered only for the rays [first, end): it cannot meet the others. */
    public void narrow(int i, int first, int end) {
        firstRay[i] = first;
        endRay[i] = end;
    }

    /**
     * The nearest hits among the gathered primitives of the rays r in [0, n) from the common
     * origin o along (dx[r], dy[r], dz[r]), each primitive searched for its range of them
     * ({@link #narrow}; all of them unless narrowed): nearestT[r] and nearestPrimitive[r] become the distance
     * and number of each ray's nearest hit, or {@link Intersect#MISS} and {@link Hit#NONE}; where two
     * are met at the same distance, the one gathered first.
     */
    public void nearestFromOrigin(Primitives p, double ox, double oy, double oz, double[] dx, double[] dy,
                                  double[] dz, int n, double[] nearestT, int[] nearestPrimitive) {
        Arrays.fill(nearestT, 0, n, Intersect.MISS);
        Arrays.fill(nearestPrimitive, 0, n, Hit.NONE);
        for (int i = 0; i < count; i++) {
            int first = Math.max(0, firstRay[i]), end = Math.min(n, endRay[i]);
            if (first < end) {
                p.nearestFromOrigin(primitives[i], ox, oy, oz, dx, dy, dz, first, end, nearestT, nearestPrimitive);
            }
        }
    }
}
