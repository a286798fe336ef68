package glint.geometry;

import java.util.Arrays;

/**
 * A filter in front of another aggregate: a ray inside a closed primitive that nothing else
 * reaches into (a glass sphere resting on a floor, say) can only leave it, so its nearest hit is
 * that primitive's, found without a search. A ray that misses it (its origin pushed past the
 * primitive by an offset larger than the primitive) is searched like any other. Which interiors
 * are empty is worked out once, when the scene is compiled: every closed primitive's bounding ball
 * against the other primitives.
 */
public final class EmptyInteriors extends AggregateFilter {

    /** Per primitive: whether it is closed and nothing else reaches into it. */
    private final boolean[] empty;

    private EmptyInteriors(Aggregate searched, boolean[] empty) {
        super(searched);
        this.empty = empty;
    }

    /** The filter in front of {@code searched}, or {@code searched} itself when no interior is empty. */
    public static Aggregate around(Aggregate searched) {
        boolean[] empty = findEmpty(searched.primitives());
        for (boolean e : empty) {
            if (e) {
                return new EmptyInteriors(searched, empty);
            }
        }
        return searched;
    }

    /** Whether primitive p is closed and nothing else reaches into it. */
    public boolean isEmpty(int p) {
        return empty[p];
    }

    @Override
    public boolean nearest(double ox, double oy, double oz, double dx, double dy, double dz, double tMax, int skip,
                           int inside, Hit hit, TraversalStack stack) {
        if (inside != Hit.NONE && empty[inside]) {
            double t = primitives.intersect(inside, ox, oy, oz, dx, dy, dz, tMax);
            if (t < tMax) {
                primitives.record(hit, inside, t);
                return true;
            }
            // the origin was pushed past the primitive (an offset larger than it): search as usual
        }
        return searched.nearest(ox, oy, oz, dx, dy, dz, tMax, skip, inside, hit, stack);
    }

    /**
     * Marks the closed primitives no other primitive reaches into: the unbounded ones are asked
     * for each; the bounded ones only where their boxes overlap along the axis the boxes spread
     * most on (a sweep over the boxes sorted by their low end), so a scene of many spheres is not
     * checked pair by pair. A pair is asked only while one of the two may still be empty: once a
     * primitive is reached, the sweep steps from it straight to the next one that may still be
     * empty ({@link StillEmpty}), so coincident, nested or overlapping primitives, which reach
     * into each other, take a number of tests that grows with their count, not its square.
     */
    static boolean[] findEmpty(Primitives p) {
        return findEmpty(p, new long[1]);
    }

    /** As {@link #findEmpty(Primitives)}, adding to {@code pairs[0]} the number of pairs it looked at. */
    static boolean[] findEmpty(Primitives p, long[] pairs) {
        int n = p.count();
        boolean[] empty = new boolean[n];
        double[] boxes = new double[6 * n];
        Integer[] boundedOnes = new Integer[n];
        int bounded = 0;
        for (int q = 0; q < n; q++) {
            p.bounds(q, boxes, 6 * q);
            empty[q] = p.closed(q) && p.bounded(q);
            if (p.bounded(q)) {
                boundedOnes[bounded++] = q;
            }
        }
        Integer[] sorted = Arrays.copyOf(boundedOnes, bounded);
        int axis = widestAxis(boxes, sorted);
        Arrays.sort(sorted, (a, b) -> Double.compare(boxes[6 * a + axis], boxes[6 * b + axis]));
        StillEmpty still = new StillEmpty(sorted, empty);
        double[] ball = new double[4];
        for (int i = 0; i < bounded; i++) {
            int a = sorted[i];
            double end = boxes[6 * a + 3 + axis];
            for (int j = empty[a] ? i + 1 : still.from(i + 1); j < bounded && boxes[6 * sorted[j] + axis] <= end;
                 j = empty[a] ? j + 1 : still.from(j + 1)) {
                int b = sorted[j];
                pairs[0]++;
                if (boxesOverlap(boxes, a, b)) {
                    markIfReached(p, a, b, ball, empty, still);
                    markIfReached(p, b, a, ball, empty, still);
                }
            }
        }
        for (int u : p.unbounded()) {
            for (int j = still.from(0); j < bounded; j = still.from(j + 1)) {
                pairs[0]++;
                markIfReached(p, sorted[j], u, ball, empty, still);
            }
        }
        return empty;
    }

    /**
     * The positions in the sweep's order of the primitives that may still be empty, each found in
     * nearly constant time: a position no longer empty points on to the next (with its path
     * shortened as it is followed).
     */
    private static final class StillEmpty {
        private final int[] next;
        private final int[] position;

        StillEmpty(Integer[] sorted, boolean[] empty) {
            next = new int[sorted.length + 1];
            position = new int[empty.length];
            for (int i = 0; i < sorted.length; i++) {
                position[sorted[i]] = i;
                next[i] = empty[sorted[i]] ? i : i + 1;
            }
            next[sorted.length] = sorted.length;
        }

        /** The first position at or after i whose primitive may still be empty, or the count. */
        int from(int i) {
            while (next[i] != i) {
                next[i] = next[next[i]];
                i = next[i];
            }
            return i;
        }

        void reached(int primitive) {
            int i = position[primitive];
            next[i] = i + 1;
        }
    }

    /** Clears {@code empty[a]} if primitive {@code other} reaches into a's bounding ball. */
    private static void markIfReached(Primitives p, int a, int other, double[] ball, boolean[] empty, StillEmpty still) {
        if (!empty[a]) {
            return;
        }
        p.kind(p.kindOf(a)).boundingBall(p.indexOf(a), ball);
        if (p.kind(p.kindOf(other)).reachesInto(p.indexOf(other), ball[0], ball[1], ball[2], ball[3])) {
            empty[a] = false;
            still.reached(a);
        }
    }

    private static int widestAxis(double[] boxes, Integer[] primitives) {
        int widest = 0;
        double widestSpread = -1;
        for (int axis = 0; axis < 3; axis++) {
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (int q : primitives) {
                lo = Math.min(lo, boxes[6 * q + axis]);
                hi = Math.max(hi, boxes[6 * q + axis]);
            }
            if (hi - lo > widestSpread) {
                widestSpread = hi - lo;
                widest = axis;
            }
        }
        return widest;
    }

    private static boolean boxesOverlap(double[] boxes, int a, int b) {
        for (int axis = 0; axis < 3; axis++) {
            if (boxes[6 * a + axis] > boxes[6 * b + 3 + axis] || boxes[6 * b + axis] > boxes[6 * a + 3 + axis]) {
                return false;
            }
        }
        return true;
    }
}
