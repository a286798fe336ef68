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
    @Override
    public boolean emptyInside(int p) {
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
     * checked pair by pair.
     */
    static boolean[] findEmpty(Primitives p) {
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
        double[] ball = new double[4];
        for (int i = 0; i < bounded; i++) {
            int a = sorted[i];
            for (int j = i + 1; j < bounded && boxes[6 * sorted[j] + axis] <= boxes[6 * a + 3 + axis]; j++) {
                int b = sorted[j];
                if (boxesOverlap(boxes, a, b)) {
                    markIfReached(p, a, b, ball, empty);
                    markIfReached(p, b, a, ball, empty);
                }
            }
        }
        for (int u = 0; u < n; u++) {
            if (!p.bounded(u)) {
                for (int q = 0; q < n; q++) {
                    markIfReached(p, q, u, ball, empty);
                }
            }
        }
        return empty;
    }

    /** Clears {@code empty[a]} if primitive {@code other} reaches into a's bounding ball. */
    private static void markIfReached(Primitives p, int a, int other, double[] ball, boolean[] empty) {
        if (!empty[a]) {
            return;
        }
        p.kind(p.kindOf(a)).boundingBall(p.indexOf(a), ball);
        if (p.kind(p.kindOf(other)).reachesInto(p.indexOf(other), ball[0], ball[1], ball[2], ball[3])) {
            empty[a] = false;
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
