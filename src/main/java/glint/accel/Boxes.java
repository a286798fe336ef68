package glint.accel;

import java.util.Arrays;

/** Axis-aligned boxes as 6 doubles in an array (min x, y, z, max x, y, z from an offset), and points by axis. */
final class Boxes {

    private Boxes() {
    }

    /** Makes the box at {@code at} empty: every min +infinity, every max -infinity. */
    static void empty(double[] box, int at) {
        Arrays.fill(box, at, at + 3, Double.POSITIVE_INFINITY);
        Arrays.fill(box, at + 3, at + 6, Double.NEGATIVE_INFINITY);
    }

    /** Grows the box at {@code at} to hold the box at {@code from} of {@code other}. */
    static void grow(double[] box, int at, double[] other, int from) {
        for (int axis = 0; axis < 3; axis++) {
            box[at + axis] = Math.min(box[at + axis], other[from + axis]);
            box[at + 3 + axis] = Math.max(box[at + 3 + axis], other[from + 3 + axis]);
        }
    }

    /** Half the surface area of the box at 0; 0 for an empty one. */
    static double halfArea(double[] box) {
        double x = box[3] - box[0], y = box[4] - box[1], z = box[5] - box[2];
        return x < 0 ? 0 : x * y + y * z + z * x;
    }

    /** Whether the boxes at {@code a} and {@code b} of {@code boxes} overlap (touching counts). */
    static boolean overlap(double[] boxes, int a, int b) {
        for (int axis = 0; axis < 3; axis++) {
            if (boxes[a + axis] > boxes[b + 3 + axis] || boxes[b + axis] > boxes[a + 3 + axis]) {
                return false;
            }
        }
        return true;
    }

    /**
     * The axis (0, 1, 2) along which the points of {@code items[from]} to {@code items[end - 1]}
     * spread most, the first such on a tie: item i's point is {@code coordinates[stride * i]} to
     * {@code [stride * i + 2]}.
     */
    static int widestAxis(double[] coordinates, int stride, int[] items, int from, int end) {
        int widest = 0;
        double widestSpread = -1;
        for (int axis = 0; axis < 3; axis++) {
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (int k = from; k < end; k++) {
                double c = coordinates[stride * items[k] + axis];
                lo = Math.min(lo, c);
                hi = Math.max(hi, c);
            }
            if (hi - lo > widestSpread) {
                widestSpread = hi - lo;
                widest = axis;
            }
        }
        return widest;
    }
}
