package glint.render;

import java.util.Arrays;

/**
 * A bounding volume hierarchy over spheres, in flat arrays. Building it reorders the spheres so
 * that every leaf covers a contiguous range of the scene's sphere arrays. Nodes are split at the
 * best of a few binned surface-area-heuristic candidates along the widest centroid axis.
 */
final class SphereBvh {

    /** Spheres per leaf at most. */
    static final int LEAF_SIZE = 4;
    private static final int BINS = 12;

    /** Node bounds: min x, y, z, max x, y, z; 6 doubles a node. */
    final double[] bounds;
    /**
     * Node links, 2 ints a node: for a leaf the first sphere and the sphere count (> 0); for an
     * inner node the index of its left child (the right child follows it) and 0.
     */
    final int[] links;
    final int nodeCount;
    /** Levels below the root on the longest path to a leaf: a traversal keeps at most this many nodes waiting. */
    final int depth;
    /** The sphere order the arrays were rearranged into: position i holds the old sphere order[i]. */
    final int[] order;

    private final double[] centroids;
    private final double[] sphereBounds;
    private int used;

    private SphereBvh(double[] spheres, int count) {
        order = new int[count];
        centroids = new double[3 * count];
        sphereBounds = new double[6 * count];
        for (int i = 0; i < count; i++) {
            order[i] = i;
            double r = spheres[4 * i + 3];
            for (int axis = 0; axis < 3; axis++) {
                double c = spheres[4 * i + axis];
                centroids[3 * i + axis] = c;
                sphereBounds[6 * i + axis] = c - r;
                sphereBounds[6 * i + 3 + axis] = c + r;
            }
        }
        int maxNodes = Math.max(1, 2 * count - 1);
        bounds = new double[6 * maxNodes];
        links = new int[2 * maxNodes];
        used = 1;
        depth = build(0, 0, count);
        nodeCount = used;
    }

    /** Builds a hierarchy over {@code count} spheres (cx, cy, cz, r each). */
    static SphereBvh build(double[] spheres, int count) {
        return new SphereBvh(spheres, count);
    }

    /** Builds the subtree of {@code node} over spheres [first, first + count); returns its depth. */
    private int build(int node, int first, int count) {
        fitBounds(node, first, count);
        if (count <= LEAF_SIZE) {
            makeLeaf(node, first, count);
            return 0;
        }
        int axis = widestCentroidAxis(first, count);
        int split = partition(first, count, axis);
        if (split <= first || split >= first + count) {
            split = first + count / 2; // all centroids in one bin: split the sorted middle
            sortByAxis(first, count, axis);
        }
        int left = used;
        used += 2;
        links[2 * node] = left;
        links[2 * node + 1] = 0;
        int leftDepth = build(left, first, split - first);
        int rightDepth = build(left + 1, split, first + count - split);
        return 1 + Math.max(leftDepth, rightDepth);
    }

    private void makeLeaf(int node, int first, int count) {
        links[2 * node] = first;
        links[2 * node + 1] = count;
    }

    private void fitBounds(int node, int first, int count) {
        double[] box = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE,
                -Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (int i = first; i < first + count; i++) {
            int s = order[i];
            for (int axis = 0; axis < 3; axis++) {
                box[axis] = Math.min(box[axis], sphereBounds[6 * s + axis]);
                box[3 + axis] = Math.max(box[3 + axis], sphereBounds[6 * s + 3 + axis]);
            }
        }
        System.arraycopy(box, 0, bounds, 6 * node, 6);
    }

    private int widestCentroidAxis(int first, int count) {
        double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] hi = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (int i = first; i < first + count; i++) {
            for (int axis = 0; axis < 3; axis++) {
                double c = centroids[3 * order[i] + axis];
                lo[axis] = Math.min(lo[axis], c);
                hi[axis] = Math.max(hi[axis], c);
            }
        }
        int widest = 0;
        for (int axis = 1; axis < 3; axis++) {
            if (hi[axis] - lo[axis] > hi[widest] - lo[widest]) {
                widest = axis;
            }
        }
        return widest;
    }

    /**
     * Partitions [first, first + count) at the binned SAH split along {@code axis}; returns the
     * index of the first sphere on the right.
     */
    private int partition(int first, int count, int axis) {
        double lo = Double.MAX_VALUE, hi = -Double.MAX_VALUE;
        for (int i = first; i < first + count; i++) {
            double c = centroids[3 * order[i] + axis];
            lo = Math.min(lo, c);
            hi = Math.max(hi, c);
        }
        if (hi <= lo) {
            return first;
        }
        int[] binCount = new int[BINS];
        double[][] binBox = new double[BINS][];
        double scale = BINS / (hi - lo) * (1 - 1e-9);
        for (int i = first; i < first + count; i++) {
            int s = order[i];
            int bin = (int) ((centroids[3 * s + axis] - lo) * scale);
            binCount[bin]++;
            binBox[bin] = grow(binBox[bin], s);
        }
        double bestCost = Double.MAX_VALUE;
        int bestBin = -1;
        for (int split = 1; split < BINS; split++) {
            double[] left = null, right = null;
            int nLeft = 0, nRight = 0;
            for (int b = 0; b < split; b++) {
                left = merge(left, binBox[b]);
                nLeft += binCount[b];
            }
            for (int b = split; b < BINS; b++) {
                right = merge(right, binBox[b]);
                nRight += binCount[b];
            }
            if (nLeft == 0 || nRight == 0) {
                continue;
            }
            double cost = area(left) * nLeft + area(right) * nRight;
            if (cost < bestCost) {
                bestCost = cost;
                bestBin = split;
            }
        }
        if (bestBin < 0) {
            return first;
        }
        int mid = first;
        for (int i = first; i < first + count; i++) {
            int s = order[i];
            if ((int) ((centroids[3 * s + axis] - lo) * scale) < bestBin) {
                order[i] = order[mid];
                order[mid++] = s;
            }
        }
        return mid;
    }

    private void sortByAxis(int first, int count, int axis) {
        Integer[] boxed = new Integer[count];
        for (int i = 0; i < count; i++) {
            boxed[i] = order[first + i];
        }
        Arrays.sort(boxed, (a, b) -> Double.compare(centroids[3 * a + axis], centroids[3 * b + axis]));
        for (int i = 0; i < count; i++) {
            order[first + i] = boxed[i];
        }
    }

    private double[] grow(double[] box, int sphere) {
        double[] sb = Arrays.copyOfRange(sphereBounds, 6 * sphere, 6 * sphere + 6);
        return merge(box, sb);
    }

    private static double[] merge(double[] a, double[] b) {
        if (a == null) {
            return b == null ? null : b.clone();
        }
        if (b == null) {
            return a;
        }
        double[] m = new double[6];
        for (int axis = 0; axis < 3; axis++) {
            m[axis] = Math.min(a[axis], b[axis]);
            m[3 + axis] = Math.max(a[3 + axis], b[3 + axis]);
        }
        return m;
    }

    private static double area(double[] box) {
        double x = box[3] - box[0], y = box[4] - box[1], z = box[5] - box[2];
        return x * y + y * z + z * x;
    }
}
