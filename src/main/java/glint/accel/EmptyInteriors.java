package glint.accel;

import glint.geometry.Primitives;
import glint.geometry.PrimitiveKind;
import glint.geometry.Hit;
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
     * checked pair by pair. A pair is asked only while one of the two may still be empty: once a
     * primitive is reached, the sweep steps from it straight to the next one that may still be
     * empty ({@link StillEmpty}), so coincident, nested or overlapping primitives, which reach
     * into each other, take a number of tests that grows with their count, not its square.
     */
    static boolean[] findEmpty(Primitives p) {
        return findEmpty(p, new long[1]);
    }

    /**
     * As {@link #findEmpty(Primitives)}, adding to {@code pairs[0]} the number of pairs it looked at;
     * each plane (an unbounded primitive whose kind {@link PrimitiveKind#reachesIntoWithinRounding}) is
     * asked of groups of the primitives still empty ({@link Groups}) once planes times
     * those primitives are more than {@link AggregatePolicy#EMPTY_PLANE_PAIRS_ONE_BY_ONE}.
     */
    static boolean[] findEmpty(Primitives p, long[] pairs) {
        return findEmpty(p, pairs, AggregatePolicy.EMPTY_PLANE_PAIRS_ONE_BY_ONE);
    }

    /** As {@link #findEmpty(Primitives, long[])}, planes asked of groups above {@code onePlaneByOne} pairs. */
    static boolean[] findEmpty(Primitives p, long[] pairs, long onePlaneByOne) {
        int n = p.count();
        boolean[] empty = new boolean[n];
        double[] boxes = new double[6 * n];
        int[] boundedOnes = new int[n];
        int bounded = 0;
        for (int q = 0; q < n; q++) {
            p.bounds(q, boxes, 6 * q);
            empty[q] = p.closed(q) && p.bounded(q);
            if (p.bounded(q)) {
                boundedOnes[bounded++] = q;
            }
        }
        int axis = Boxes.widestAxis(boxes, 6, boundedOnes, 0, bounded);
        Integer[] sorted = Arrays.stream(boundedOnes, 0, bounded).boxed().toArray(Integer[]::new);
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
                if (Boxes.overlap(boxes, 6 * a, 6 * b)) {
                    markIfReached(p, a, b, ball, empty, still);
                    markIfReached(p, b, a, ball, empty, still);
                }
            }
        }
        int[] unbounded = p.unbounded();
        Groups groups = null;
        for (int u : unbounded) {
            if (groups == null && p.kind(p.kindOf(u)).reachesIntoWithinRounding()) {
                int left = 0;
                for (int j = still.from(0); j < bounded; j = still.from(j + 1)) {
                    left++;
                }
                if ((long) left * unbounded.length > onePlaneByOne) {
                    groups = new Groups(p, sorted, still, left);
                }
            }
            if (groups != null && p.kind(p.kindOf(u)).reachesIntoWithinRounding()) {
                groups.markReachedBy(p, u, 0, ball, empty, still, pairs);
                continue;
            }
            for (int j = still.from(0); j < bounded; j = still.from(j + 1)) {
                pairs[0]++;
                markIfReached(p, sorted[j], u, ball, empty, still);
            }
        }
        return empty;
    }

    /**
     * The primitives still empty after the sweep, in nested groups for the planes: each group in a
     * ball (split at the median of the widest spread of its members' centres, at most
     * {@link #LEAF} a leaf). A plane that does not reach into a group's ball widened by 1e-9 of its
     * size and distance from the origin reaches into none of its members' balls: a plane's test
     * (|n.c - d| < r with a unit n) errs by about 1e-16 of those, so the widening covers every
     * rounding. Far planes are so set aside a group at a time instead of member by member.
     */
    private static final class Groups {
        static final int LEAF = AggregatePolicy.EMPTY_GROUP_LEAF;
        /** Beyond this size or distance, a group's ball is not trusted and its members are asked. */
        static final double LARGEST = 1e150;

        private final int[] members;
        private final double[] balls; // per member: centre x, y, z, radius
        private final java.util.List<double[]> nodes = new java.util.ArrayList<>(); // x, y, z, reach, from, to, left, right

        Groups(Primitives p, Integer[] sorted, StillEmpty still, int count) {
            members = new int[count];
            balls = new double[4 * count];
            double[] ball = new double[4];
            int m = 0;
            for (int j = still.from(0); j < sorted.length; j = still.from(j + 1)) {
                members[m] = sorted[j];
                p.kind(p.kindOf(sorted[j])).boundingBall(p.indexOf(sorted[j]), ball);
                System.arraycopy(ball, 0, balls, 4 * m, 4);
                m++;
            }
            build(0, count);
        }

        /** Makes the node of members [from, to) and those below it; returns its index. */
        private int build(int from, int to) {
            double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
            double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
            for (int m = from; m < to; m++) {
                for (int k = 0; k < 3; k++) {
                    lo[k] = Math.min(lo[k], balls[4 * m + k]);
                    hi[k] = Math.max(hi[k], balls[4 * m + k]);
                }
            }
            double cx = lo[0] / 2 + hi[0] / 2, cy = lo[1] / 2 + hi[1] / 2, cz = lo[2] / 2 + hi[2] / 2;
            double radius = 0;
            for (int m = from; m < to; m++) {
                double ex = balls[4 * m] - cx, ey = balls[4 * m + 1] - cy, ez = balls[4 * m + 2] - cz;
                radius = Math.max(radius, Math.sqrt(ex * ex + ey * ey + ez * ez) + balls[4 * m + 3]);
            }
            radius *= 1 + 1e-12; // holds every member's ball despite the rounding of the lines above
            double distance = Math.sqrt(cx * cx + cy * cy + cz * cz);
            double reach = radius * (1 + 1e-9) + 1e-9 * distance;
            boolean trusted = reach + distance < LARGEST; // finite, and far from overflow
            double[] node = {cx, cy, cz, trusted ? reach : Double.NaN, from, to, -1, -1};
            int index = nodes.size();
            nodes.add(node);
            if (to - from > LEAF) {
                int axis = hi[0] - lo[0] >= hi[1] - lo[1] && hi[0] - lo[0] >= hi[2] - lo[2] ? 0
                        : hi[1] - lo[1] >= hi[2] - lo[2] ? 1 : 2;
                sortByCentre(from, to, axis);
                int middle = (from + to) >>> 1;
                node[6] = build(from, middle);
                node[7] = build(middle, to);
            }
            return index;
        }

        /** Sorts members [from, to) by their centres along the axis, balls with them. */
        private void sortByCentre(int from, int to, int axis) {
            Integer[] order = new Integer[to - from];
            for (int m = from; m < to; m++) {
                order[m - from] = m;
            }
            Arrays.sort(order, (a, b) -> Double.compare(balls[4 * a + axis], balls[4 * b + axis]));
            int[] memberCopy = Arrays.copyOfRange(members, from, to);
            double[] ballCopy = Arrays.copyOfRange(balls, 4 * from, 4 * to);
            for (int i = 0; i < order.length; i++) {
                members[from + i] = memberCopy[order[i] - from];
                System.arraycopy(ballCopy, 4 * (order[i] - from), balls, 4 * (from + i), 4);
            }
        }

        /** Clears the empty mark of every member of node {@code at} that plane u reaches into. */
        void markReachedBy(Primitives p, int u, int at, double[] ball, boolean[] empty, StillEmpty still, long[] pairs) {
            double[] node = nodes.get(at);
            pairs[0]++;
            PrimitiveKind planes = p.kind(p.kindOf(u));
            if (!Double.isNaN(node[3]) && !planes.reachesInto(p.indexOf(u), node[0], node[1], node[2], node[3])) {
                return;
            }
            if (node[6] < 0) {
                for (int m = (int) node[4]; m < (int) node[5]; m++) {
                    pairs[0]++;
                    markIfReached(p, members[m], u, ball, empty, still);
                }
                return;
            }
            markReachedBy(p, u, (int) node[6], ball, empty, still, pairs);
            markReachedBy(p, u, (int) node[7], ball, empty, still, pairs);
        }
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
}
