package glint.accel;

import glint.geometry.Primitives;
import java.util.Arrays;

/**
 * Builds a {@link Bvh}'s arrays: the bounded primitives ordered so that each leaf covers a
 * contiguous run, nodes split at the best of {@link #BINS} binned surface-area-heuristic
 * candidates along the widest centroid axis, or at the middle when the centroids do not spread.
 */
final class BvhBuilder {

    private static final int BINS = AggregatePolicy.BVH_BINS;

    private final int leafSize;
    private final int[] order;
    private final int[] unbounded;
    /** Box and centroid of the i-th bounded primitive (in {@link #order}'s numbering of slots). */
    private final double[] boxes, centroids;
    /** Per slot of {@link #order}, once built: its primitive's box. */
    private final double[] slotBoxes;
    private final double[] nodeBox;
    private final int[] links;
    private int used;
    private final int depth;

    BvhBuilder(Primitives primitives, int leafSize) {
        this.leafSize = leafSize;
        unbounded = primitives.unbounded();
        int bounded = primitives.count() - unbounded.length;
        int[] boundedNumbers = new int[bounded];
        for (int p = 0, b = 0; p < primitives.count(); p++) {
            if (primitives.bounded(p)) {
                boundedNumbers[b++] = p;
            }
        }
        boxes = new double[6 * bounded];
        centroids = new double[3 * bounded];
        order = new int[bounded]; // local indices 0..bounded-1 while building, primitive numbers after
        for (int i = 0; i < bounded; i++) {
            primitives.bounds(boundedNumbers[i], boxes, 6 * i);
            for (int axis = 0; axis < 3; axis++) {
                centroids[3 * i + axis] = 0.5 * (boxes[6 * i + axis] + boxes[6 * i + 3 + axis]);
            }
            order[i] = i;
        }
        int maxNodes = Math.max(1, 2 * bounded - 1);
        nodeBox = new double[6 * maxNodes];
        links = new int[2 * maxNodes];
        used = bounded > 0 ? 1 : 0;
        depth = bounded > 0 ? build(0, 0, bounded) : 0;
        slotBoxes = new double[6 * bounded];
        for (int i = 0; i < bounded; i++) {
            System.arraycopy(boxes, 6 * order[i], slotBoxes, 6 * i, 6);
            order[i] = boundedNumbers[order[i]];
        }
    }

    double[] nodeBox() {
        return Arrays.copyOf(nodeBox, 6 * used);
    }

    int[] links() {
        return Arrays.copyOf(links, 2 * used);
    }

    int nodeCount() {
        return used;
    }

    int depth() {
        return depth;
    }

    /** Each slot's primitive's box (min x, y, z, max x, y, z), 6 doubles a slot in {@link #order}'s order. */
    double[] slotBoxes() {
        return slotBoxes;
    }

    int[] order() {
        return order;
    }

    int[] unbounded() {
        return unbounded;
    }

    /** Builds the subtree of {@code node} over slots [first, first + count); returns its depth. */
    private int build(int node, int first, int count) {
        fitBox(node, first, count);
        if (count <= leafSize) {
            links[2 * node] = first;
            links[2 * node + 1] = count;
            return 0;
        }
        int axis = Boxes.widestAxis(centroids, 3, order, first, first + count);
        int split = partition(first, count, axis);
        if (split <= first || split >= first + count) {
            sortByAxis(first, count, axis);
            split = first + count / 2;
        }
        int left = used;
        used += 2;
        links[2 * node] = left;
        links[2 * node + 1] = 0;
        int leftDepth = build(left, first, split - first);
        int rightDepth = build(left + 1, split, first + count - split);
        return 1 + Math.max(leftDepth, rightDepth);
    }

    private void fitBox(int node, int first, int count) {
        Boxes.empty(nodeBox, 6 * node);
        for (int slot = first; slot < first + count; slot++) {
            Boxes.grow(nodeBox, 6 * node, boxes, 6 * order[slot]);
        }
    }

    /**
     * Partitions slots [first, first + count) at the cheapest binned SAH split along {@code axis};
     * returns the first slot on the right, or {@code first} when no split separates them.
     */
    private int partition(int first, int count, int axis) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (int slot = first; slot < first + count; slot++) {
            double c = centroids[3 * order[slot] + axis];
            lo = Math.min(lo, c);
            hi = Math.max(hi, c);
        }
        double scale = BINS / (hi - lo) * (1 - 1e-9);
        if (!(hi > lo) || !Double.isFinite(scale)) {
            return first;
        }
        int[] binCount = new int[BINS];
        double[] binBox = new double[6 * BINS];
        for (int b = 0; b < BINS; b++) {
            Boxes.empty(binBox, 6 * b);
        }
        for (int slot = first; slot < first + count; slot++) {
            int bin = binOf(order[slot], axis, lo, scale);
            binCount[bin]++;
            Boxes.grow(binBox, 6 * bin, boxes, 6 * order[slot]);
        }
        double bestCost = Double.POSITIVE_INFINITY;
        int bestBin = -1;
        double[] left = new double[6], right = new double[6];
        for (int split = 1; split < BINS; split++) {
            Boxes.empty(left, 0);
            Boxes.empty(right, 0);
            int nLeft = 0, nRight = 0;
            for (int b = 0; b < BINS; b++) {
                if (b < split) {
                    Boxes.grow(left, 0, binBox, 6 * b);
                    nLeft += binCount[b];
                } else {
                    Boxes.grow(right, 0, binBox, 6 * b);
                    nRight += binCount[b];
                }
            }
            if (nLeft > 0 && nRight > 0) {
                double cost = Boxes.halfArea(left) * nLeft + Boxes.halfArea(right) * nRight;
                if (cost < bestCost) {
                    bestCost = cost;
                    bestBin = split;
                }
            }
        }
        if (bestBin < 0) {
            return first;
        }
        int mid = first;
        for (int slot = first; slot < first + count; slot++) {
            int i = order[slot];
            if (binOf(i, axis, lo, scale) < bestBin) {
                order[slot] = order[mid];
                order[mid++] = i;
            }
        }
        return mid;
    }

    private int binOf(int i, int axis, double lo, double scale) {
        return Math.min(BINS - 1, (int) ((centroids[3 * i + axis] - lo) * scale));
    }

    private void sortByAxis(int first, int count, int axis) {
        Integer[] boxed = new Integer[count];
        for (int k = 0; k < count; k++) {
            boxed[k] = order[first + k];
        }
        Arrays.sort(boxed, (a, b) -> Double.compare(centroids[3 * a + axis], centroids[3 * b + axis]));
        for (int k = 0; k < count; k++) {
            order[first + k] = boxed[k];
        }
    }
}
