package glint.accel;

import glint.geometry.Primitives;
import java.util.Arrays;

/**
 * The empty interiors as the scene compiler found them before it skipped settled pairs: every pair
 * of bounded primitives whose boxes overlap is asked (a sweep along the widest axis), every
 * unbounded primitive against every primitive. Quadratic for primitives that all overlap; kept as
 * the answer {@link EmptyInteriors#findEmpty} must give.
 */
final class PairSweepReference {

    private PairSweepReference() {
    }

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
        int axis = 0;
        double widestSpread = -1;
        for (int k = 0; k < 3; k++) {
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (int q : sorted) {
                lo = Math.min(lo, boxes[6 * q + k]);
                hi = Math.max(hi, boxes[6 * q + k]);
            }
            if (hi - lo > widestSpread) {
                widestSpread = hi - lo;
                axis = k;
            }
        }
        int along = axis;
        Arrays.sort(sorted, (a, b) -> Double.compare(boxes[6 * a + along], boxes[6 * b + along]));
        double[] ball = new double[4];
        for (int i = 0; i < bounded; i++) {
            int a = sorted[i];
            for (int j = i + 1; j < bounded && boxes[6 * sorted[j] + along] <= boxes[6 * a + 3 + along]; j++) {
                int b = sorted[j];
                if (overlap(boxes, a, b)) {
                    mark(p, a, b, ball, empty);
                    mark(p, b, a, ball, empty);
                }
            }
        }
        for (int u = 0; u < n; u++) {
            if (!p.bounded(u)) {
                for (int q = 0; q < n; q++) {
                    mark(p, q, u, ball, empty);
                }
            }
        }
        return empty;
    }

    private static void mark(Primitives p, int a, int other, double[] ball, boolean[] empty) {
        if (!empty[a]) {
            return;
        }
        p.kind(p.kindOf(a)).boundingBall(p.indexOf(a), ball);
        if (p.kind(p.kindOf(other)).reachesInto(p.indexOf(other), ball[0], ball[1], ball[2], ball[3])) {
            empty[a] = false;
        }
    }

    private static boolean overlap(double[] boxes, int a, int b) {
        for (int k = 0; k < 3; k++) {
            if (boxes[6 * a + k] > boxes[6 * b + 3 + k] || boxes[6 * b + k] > boxes[6 * a + 3 + k]) {
                return false;
            }
        }
        return true;
    }
}
