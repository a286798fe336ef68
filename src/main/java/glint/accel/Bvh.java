package glint.accel;

import glint.geometry.Hit;
import glint.geometry.Intersect;
import glint.geometry.Primitives;

/**
 * A bounding volume hierarchy over the bounded primitives, in flat arrays; the unbounded ones
 * (planes) are tested by every ray before it. Nodes split at the best of a few binned
 * surface-area-heuristic candidates along the widest centroid axis. Both queries walk it the same
 * way ({@link #nextLeaf}): a nearest-hit search visits the nearer child first and passes over a
 * waiting node the ray enters beyond the nearest hit so far; a transmittance visits the left child
 * first, so the light passed is multiplied in one fixed order. The stack holds at most one node a
 * level, so {@link #newStack} sizes it from the tree's depth.
 */
public final class Bvh implements Aggregate {

    /** How far a box's far distance is widened, relative: 8 rounding steps of a double (derived, not tuned). */
    private static final double GRAZE = 8 * 0x1p-53;

    private final Primitives primitives;
    /** Node boxes: min x, y, z, max x, y, z; 6 doubles a node. */
    private final double[] nodeBox;
    /**
     * Node links, 2 ints a node: for a leaf its first slot in {@link #leaves} and its primitive
     * count (> 0); for an inner node its left child (the right one follows it) and 0.
     */
    private final int[] links;
    private final int nodeCount;
    /** Levels below the root on the longest path to a leaf. */
    private final int depth;
    /** The bounded primitives, each leaf's a contiguous run of slots. */
    private final PrimitiveSlots leaves;
    /** Per slot of {@link #leaves}: its primitive's box, 6 doubles a slot. */
    private final double[] slotBox;
    /** The unbounded primitives. */
    private final PrimitiveSlots unbounded;

    public Bvh(Primitives primitives, int leafSize) {
        this.primitives = primitives;
        BvhBuilder builder = new BvhBuilder(primitives, leafSize);
        this.nodeBox = builder.nodeBox();
        this.links = builder.links();
        this.nodeCount = builder.nodeCount();
        this.depth = builder.depth();
        this.leaves = new PrimitiveSlots(primitives, builder.order());
        this.slotBox = builder.slotBoxes();
        this.unbounded = new PrimitiveSlots(primitives, builder.unbounded());
    }

    @Override
    public Primitives primitives() {
        return primitives;
    }

    @Override
    public TraversalStack newStack() {
        return new TraversalStack(depth + 1);
    }

    @Override
    public boolean nearest(double ox, double oy, double oz, double dx, double dy, double dz, double tMax, int skip,
                           int inside, Hit hit, TraversalStack stack) {
        double nearest = unbounded.nearest(0, unbounded.count(), ox, oy, oz, dx, dy, dz, tMax, skip, hit);
        double ix = 1 / nonZero(dx), iy = 1 / nonZero(dy), iz = 1 / nonZero(dz);
        for (int leaf = firstLeaf(ox, oy, oz, ix, iy, iz, nearest, true, stack); leaf >= 0;
             leaf = nextLeaf(-1, ox, oy, oz, ix, iy, iz, nearest, true, stack)) {
            int first = links[2 * leaf];
            nearest = leaves.nearest(first, first + links[2 * leaf + 1], ox, oy, oz, dx, dy, dz, nearest, skip, hit);
        }
        return nearest < tMax;
    }

    @Override
    public double transmittance(double ox, double oy, double oz, double dx, double dy, double dz, double tMax,
                                int skip, double[] pass, TraversalStack stack) {
        double passed = unbounded.transmittance(0, unbounded.count(), ox, oy, oz, dx, dy, dz, tMax, skip, pass, 1);
        double ix = 1 / nonZero(dx), iy = 1 / nonZero(dy), iz = 1 / nonZero(dz);
        for (int leaf = passed == 0 ? -1 : firstLeaf(ox, oy, oz, ix, iy, iz, tMax, false, stack); leaf >= 0;
             leaf = nextLeaf(-1, ox, oy, oz, ix, iy, iz, tMax, false, stack)) {
            int first = links[2 * leaf];
            passed = leaves.transmittance(first, first + links[2 * leaf + 1], ox, oy, oz, dx, dy, dz, tMax, skip,
                    pass, passed);
            if (passed == 0) {
                return 0;
            }
        }
        return passed;
    }

    /** The first leaf of a walk ({@link #nextLeaf}) from the root, emptying the stack first. */
    private int firstLeaf(double ox, double oy, double oz, double ix, double iy, double iz, double limit,
                          boolean nearerFirst, TraversalStack stack) {
        stack.waiting = 0;
        int root = nodeCount > 0 && boxEntry(0, ox, oy, oz, ix, iy, iz) < limit ? 0 : -1;
        return nextLeaf(root, ox, oy, oz, ix, iy, iz, limit, nearerFirst, stack);
    }

    /**
     * The next leaf whose box the ray (from o, reciprocal direction i) enters before {@code limit},
     * or -1 when none is left: descending from {@code node} (a node it enters before the limit), or
     * with -1 from the nearest waiting node it still enters before the limit. At each inner node it
     * goes on into the child it enters first ({@code nearerFirst}; otherwise the left one) and keeps
     * the other waiting with its entry distance, if the ray enters it before the limit. The limit
     * may only shrink between the calls of one walk (a nearest-hit search lowers it to each hit).
     */
    private int nextLeaf(int node, double ox, double oy, double oz, double ix, double iy, double iz, double limit,
                         boolean nearerFirst, TraversalStack stack) {
        int[] waiting = stack.nodes;
        double[] entries = stack.entries;
        int top = stack.waiting;
        while (true) {
            while (node < 0) {
                if (top == 0) {
                    stack.waiting = 0;
                    return -1;
                }
                top--;
                if (entries[top] < limit) {
                    node = waiting[top];
                }
            }
            if (links[2 * node + 1] > 0) {
                stack.waiting = top;
                return node;
            }
            int left = links[2 * node];
            double enterLeft = boxEntry(left, ox, oy, oz, ix, iy, iz);
            double enterRight = boxEntry(left + 1, ox, oy, oz, ix, iy, iz);
            boolean leftFirst = !nearerFirst || enterLeft <= enterRight;
            double enterFirst = leftFirst ? enterLeft : enterRight, enterSecond = leftFirst ? enterRight : enterLeft;
            if (enterSecond < limit) {
                waiting[top] = leftFirst ? left + 1 : left;
                entries[top++] = enterSecond;
            }
            node = enterFirst < limit ? (leftFirst ? left : left + 1) : -1;
        }
    }

    @Override
    public void gather(Frustum frustum, Candidates out, TraversalStack stack) {
        out.clear();
        for (int u = 0; u < unbounded.count(); u++) {
            out.add(unbounded.number(u));
        }
        int[] waiting = stack.nodes;
        int top = 0;
        int node = nodeCount > 0 ? 0 : -1;
        while (node >= 0) {
            if (frustum.mayHold(nodeBox, 6 * node)) {
                int count = links[2 * node + 1];
                if (count == 0) {
                    waiting[top++] = links[2 * node] + 1;
                    node = links[2 * node];
                    continue;
                }
                for (int slot = links[2 * node], end = slot + count; slot < end; slot++) {
                    if (frustum.mayHold(slotBox, 6 * slot)) {
                        out.add(leaves.number(slot));
                    }
                }
            }
            node = top > 0 ? waiting[--top] : -1;
        }
    }

    /**
     * Distance along the ray to where it enters the node's box (0 when it starts inside), or
     * {@link Intersect#MISS}. Slab test with reciprocal directions; zero direction components are
     * replaced by a tiny one first, so no 0 x infinity makes a NaN. The far distance is widened by
     * a few rounding steps so that a ray grazing a box is not lost.
     */
    private double boxEntry(int node, double ox, double oy, double oz, double ix, double iy, double iz) {
        double[] box = nodeBox;
        int b = 6 * node;
        double tx0 = (box[b] - ox) * ix, tx1 = (box[b + 3] - ox) * ix;
        double ty0 = (box[b + 1] - oy) * iy, ty1 = (box[b + 4] - oy) * iy;
        double tz0 = (box[b + 2] - oz) * iz, tz1 = (box[b + 5] - oz) * iz;
        // each axis's near plane is the one the direction's sign points away from, so no min or max picks between
        // the two (they differ from the picked ones at most in a zero's sign, which no comparison sees)
        boolean bx = ix < 0, by = iy < 0, bz = iz < 0;
        double nearX = bx ? tx1 : tx0, farX = bx ? tx0 : tx1;
        double nearY = by ? ty1 : ty0, farY = by ? ty0 : ty1;
        double nearZ = bz ? tz1 : tz0, farZ = bz ? tz0 : tz1;
        double near = Math.max(Math.max(nearX, nearY), Math.max(nearZ, 0));
        double far = Math.min(Math.min(farX, farY), farZ);
        return near <= far * (1 + GRAZE) ? near : Intersect.MISS;
    }

    private static double nonZero(double component) {
        return component == 0 ? 1e-300 : component;
    }

    @Override
    public String toString() {
        return "Bvh[" + leaves.count() + " bounded, " + unbounded.count() + " unbounded, " + nodeCount
                + " nodes, depth " + depth + "]";
    }
}
