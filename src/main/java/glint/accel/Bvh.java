package glint.accel;

import glint.geometry.Primitives;
import glint.geometry.PrimitiveKind;
import glint.geometry.Intersect;
import glint.geometry.Hit;
/**
 * A bounding volume hierarchy over the bounded primitives, in flat arrays; the unbounded ones
 * (planes) are tested by every ray before it. Nodes split at the best of a few binned
 * surface-area-heuristic candidates along the widest centroid axis. The nearest-hit traversal
 * visits the nearer child first; its stack holds at most one node a level, so {@link #newStack} sizes it from the
 * tree's depth.
 */
public final class Bvh implements Aggregate {

    private final Primitives primitives;
    /** Node boxes: min x, y, z, max x, y, z; 6 doubles a node. */
    private final double[] nodeBox;
    /**
     * Node links, 2 ints a node: for a leaf its first slot in {@link #leafPrimitives} and its
     * primitive count (> 0); for an inner node its left child (the right one follows it) and 0.
     */
    private final int[] links;
    private final int nodeCount;
    /** Levels below the root on the longest path to a leaf. */
    private final int depth;
    /** The bounded primitives' numbers, each leaf's a contiguous run. */
    private final int[] leafPrimitives;
    /** Per slot of {@link #leafPrimitives}: the primitive's kind and its index within the kind. */
    private final PrimitiveKind[] leafKind;
    private final int[] leafIndex;
    /** The unbounded primitives' numbers. */
    private final int[] unbounded;

    public Bvh(Primitives primitives, int leafSize) {
        this.primitives = primitives;
        BvhBuilder builder = new BvhBuilder(primitives, leafSize);
        this.nodeBox = builder.nodeBox();
        this.links = builder.links();
        this.nodeCount = builder.nodeCount();
        this.depth = builder.depth();
        this.leafPrimitives = builder.order();
        this.unbounded = builder.unbounded();
        this.leafKind = primitives.kindsOf(leafPrimitives);
        this.leafIndex = primitives.indicesOf(leafPrimitives);
    }

    /** Levels below the root on the longest path to a leaf: a traversal keeps at most this many nodes waiting. */
    public int depth() {
        return depth;
    }

    public int nodeCount() {
        return nodeCount;
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
        Primitives p = primitives;
        double nearest = tMax;
        int found = Hit.NONE;
        for (int u : unbounded) {
            if (u != skip) {
                double t = p.intersect(u, ox, oy, oz, dx, dy, dz, nearest);
                if (t < nearest) {
                    nearest = t;
                    found = u;
                }
            }
        }
        double ix = 1 / nonZero(dx), iy = 1 / nonZero(dy), iz = 1 / nonZero(dz);
        int[] waiting = stack.nodes;
        double[] entries = stack.entries;
        int top = 0;
        int node = nodeCount > 0 && boxEntry(0, ox, oy, oz, ix, iy, iz) < nearest ? 0 : -1;
        while (node >= 0) {
            int count = links[2 * node + 1];
            if (count > 0) {
                for (int slot = links[2 * node], end = slot + count; slot < end; slot++) {
                    if (leafPrimitives[slot] != skip) {
                        double t = leafKind[slot].intersect(leafIndex[slot], ox, oy, oz, dx, dy, dz, nearest);
                        if (t < nearest) {
                            nearest = t;
                            found = leafPrimitives[slot];
                        }
                    }
                }
                node = -1;
            } else {
                int left = links[2 * node];
                double enterLeft = boxEntry(left, ox, oy, oz, ix, iy, iz);
                double enterRight = boxEntry(left + 1, ox, oy, oz, ix, iy, iz);
                boolean leftFirst = enterLeft <= enterRight;
                double enterNear = leftFirst ? enterLeft : enterRight, enterFar = leftFirst ? enterRight : enterLeft;
                node = -1;
                if (enterNear < nearest) {
                    if (enterFar < nearest) {
                        waiting[top] = leftFirst ? left + 1 : left;
                        entries[top++] = enterFar;
                    }
                    node = leftFirst ? left : left + 1;
                }
            }
            // the nearest waiting node the ray may still meet something in before the nearest hit
            while (node < 0 && top > 0) {
                top--;
                if (entries[top] < nearest) {
                    node = waiting[top];
                }
            }
        }
        if (found == Hit.NONE) {
            return false;
        }
        p.record(hit, found, nearest);
        return true;
    }

    @Override
    public double transmittance(double ox, double oy, double oz, double dx, double dy, double dz, double tMax,
                                int skip, double[] pass, TraversalStack stack) {
        Primitives p = primitives;
        double passed = 1;
        for (int u : unbounded) {
            if (u != skip && p.intersect(u, ox, oy, oz, dx, dy, dz, tMax) < tMax) {
                passed *= pass[u];
                if (passed == 0) {
                    return 0;
                }
            }
        }
        double ix = 1 / nonZero(dx), iy = 1 / nonZero(dy), iz = 1 / nonZero(dz);
        int[] waiting = stack.nodes;
        int top = 0;
        int node = nodeCount > 0 ? 0 : -1;
        while (node >= 0) {
            if (boxEntry(node, ox, oy, oz, ix, iy, iz) < tMax) {
                int count = links[2 * node + 1];
                if (count == 0) {
                    waiting[top++] = links[2 * node] + 1;
                    node = links[2 * node];
                    continue;
                }
                for (int slot = links[2 * node], end = slot + count; slot < end; slot++) {
                    int q = leafPrimitives[slot];
                    if (q != skip && leafKind[slot].intersect(leafIndex[slot], ox, oy, oz, dx, dy, dz, tMax) < tMax) {
                        passed *= pass[q];
                        if (passed == 0) {
                            return 0;
                        }
                    }
                }
            }
            node = top > 0 ? waiting[--top] : -1;
        }
        return passed;
    }

    @Override
    public void gather(Frustum frustum, Candidates out, TraversalStack stack) {
        out.clear();
        for (int u : unbounded) {
            out.add(u);
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
                    leafKind[slot].bounds(leafIndex[slot], out.box, 0);
                    if (frustum.mayHold(out.box, 0)) {
                        out.add(leafPrimitives[slot]);
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
        // Math.min and max compile to branch-free code, which a ray's unpredictable slabs need
        double near = Math.max(Math.max(Math.min(tx0, tx1), Math.min(ty0, ty1)), Math.max(Math.min(tz0, tz1), 0));
        double far = Math.min(Math.min(Math.max(tx0, tx1), Math.max(ty0, ty1)), Math.max(tz0, tz1));
        return near <= far * (1 + 8 * 0x1p-53) ? near : Intersect.MISS;
    }

    private static double nonZero(double component) {
        return component == 0 ? 1e-300 : component;
    }

    @Override
    public String toString() {
        return "Bvh[" + leafPrimitives.length + " bounded, " + unbounded.length + " unbounded, " + nodeCount
                + " nodes, depth " + depth + "]";
    }
}
