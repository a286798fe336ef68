package glint.accel;

import glint.geometry.Primitives;
import java.util.Arrays;

/**
 * Works out cube maps of direction cells, one a ball, for the filters on {@link CellFilter}: each
 * cell lists the bounded primitives a ray starting within the ball, travelling in a direction of
 * the cell, could meet (see {@link CellCones} for the geometry), or falls back to the search when
 * it would list more than {@code cap}. The primitives are walked through a tree, nearer nodes
 * first, leaving out nodes that only closed cells could reach. Worked out once, when a scene is
 * compiled.
 */
final class CellMaps {

    /** Bits of a cell's listing that hold its count: a cap is below 1 << COUNT_BITS. */
    static final int COUNT_BITS = 6;

    final Primitives primitives;
    /** Cells along a cube face's side, and the most primitives a cell lists. */
    final int k, cap;
    /** Each bounded primitive's bounding ball (centre, radius), 4 doubles from 4q. */
    final double[] balls;
    /**
     * Per cell of every map appended, in one int so that a ray reads one place: its first slot in
     * {@link #listed} shifted left by {@link #COUNT_BITS}, plus how many it lists; or -1: fall back.
     */
    int[] cell;
    /** The cells' lists of primitive numbers, each in the primitives' order. */
    int[] listed = new int[64];
    int cells, slots;

    private final CellCones cones;
    private final CellCones.Lists lists;
    private final BvhBuilder tree;
    private final double[] nodeBalls;
    private final int[] waiting;

    CellMaps(Primitives p, int k, int cap) {
        if (cap < 1 || cap >= 1 << COUNT_BITS) {
            throw new IllegalArgumentException("a cell's cap must be 1 to " + ((1 << COUNT_BITS) - 1) + ": " + cap);
        }
        this.primitives = p;
        this.k = k;
        this.cap = cap;
        this.cell = new int[6 * k * k];
        int n = p.count();
        balls = new double[4 * n];
        double[] box = new double[6];
        for (int q = 0; q < n; q++) {
            if (p.bounded(q)) {
                CellCones.ballOf(p, q, box, balls);
            }
        }
        cones = CellCones.of(k);
        lists = new CellCones.Lists(k, cap);
        tree = new BvhBuilder(p, AggregatePolicy.CELL_TREE_LEAF_SIZE);
        nodeBalls = nodeBalls(tree);
        waiting = new int[tree.depth() + 2];
    }

    /** Cells a map holds. */
    int cellsPerMap() {
        return 6 * k * k;
    }

    /**
     * Appends the map of the ball (c, reach), listing every bounded primitive but {@code exclude}
     * ({@link glint.geometry.Hit#NONE}: none); returns its first cell, or -1 (appending nothing) when every one of
     * its cells falls back.
     */
    int add(double cx, double cy, double cz, double reach, int exclude) {
        lists.reset();
        int[] links = tree.links(), order = tree.order();
        int top = 0;
        if (tree.nodeCount() > 0) {
            waiting[top++] = 0;
        }
        while (top > 0 && lists.open > 0) {
            int node = waiting[--top];
            if (!cones.reach(cx, cy, cz, reach, nodeBalls, 4 * node, -1, lists)) {
                continue;
            }
            int count = links[2 * node + 1];
            if (count == 0) {
                int left = links[2 * node];
                boolean leftNearer = distance2(nodeBalls, left, cx, cy, cz)
                        <= distance2(nodeBalls, left + 1, cx, cy, cz);
                waiting[top++] = leftNearer ? left + 1 : left;
                waiting[top++] = leftNearer ? left : left + 1;
                continue;
            }
            for (int slot = links[2 * node], end = slot + count; slot < end; slot++) {
                if (order[slot] != exclude) {
                    cones.reach(cx, cy, cz, reach, balls, 4 * order[slot], order[slot], lists);
                }
            }
        }
        return lists.open == 0 ? -1 : append();
    }

    private int append() {
        int first = cells, perMap = cellsPerMap();
        if (cells + perMap > cell.length) {
            cell = Arrays.copyOf(cell, 2 * (cells + perMap));
        }
        int[] counts = lists.counts;
        for (int c = 0; c < perMap; c++, cells++) {
            int count = counts[c];
            if (count > cap) {
                cell[cells] = -1;
                continue;
            }
            if (slots + count > listed.length) {
                listed = Arrays.copyOf(listed, 2 * (slots + count));
            }
            if (slots >= 1 << (31 - COUNT_BITS)) {
                throw new IllegalStateException("too many listed for a cell's int: " + slots);
            }
            cell[cells] = slots << COUNT_BITS | count;
            System.arraycopy(lists.lists, c * cap, listed, slots, count);
            Arrays.sort(listed, slots, slots + count); // in the primitives' order, whatever the tree's
            slots += count;
        }
        return first;
    }

    /** The ball around each node's box (it holds what the node's primitives hold). */
    private static double[] nodeBalls(BvhBuilder tree) {
        double[] box = tree.nodeBox();
        double[] ball = new double[4 * tree.nodeCount()];
        for (int node = 0; node < tree.nodeCount(); node++) {
            CellCones.boxBall(box, 6 * node, ball, 4 * node);
        }
        return ball;
    }

    private static double distance2(double[] balls, int node, double cx, double cy, double cz) {
        double ex = balls[4 * node] - cx, ey = balls[4 * node + 1] - cy, ez = balls[4 * node + 2] - cz;
        return ex * ex + ey * ey + ez * ez;
    }
}
