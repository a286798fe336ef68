package glint.geometry;

import java.util.Arrays;

/**
 * A filter in front of another aggregate for rays that leave a closed primitive on its outer side
 * (reflected off a metal or glass sphere, or leaving a glass one). For each closed bounded primitive
 * S a cube map of direction cells (6 faces of {@link #K} x K) lists the bounded primitives a ray
 * starting within S's bounding ball, travelling in a direction of the cell, could meet; such a ray
 * tests the unbounded primitives and its cell's list instead of searching. A cell that would list
 * more than {@link #CAP} falls back to the search, as does a ray whose origin is not within the
 * ball the cells were worked out for. Worked out once, when the scene is compiled. Shadow rays
 * are searched as usual: answered from the cells, they took 0.90 to 1.02 of the render CPU a frame
 * on the default scene and glass-25 (4 runs), short of 5 %.
 */
public final class LeavingCells extends AggregateFilter {

    /** Cells along a cube face's side. */
    static final int K = 8;
    static final int CELLS = 6 * K * K;
    /** The most primitives a cell lists (below 32: see {@link #cell}); a cell that would list more falls back. */
    static final int CAP = 16;
    /**
     * How far off S's bounding ball (relative to max(1, |centre| + radius)) an origin may be and still
     * use the cells: a spawned ray starts epsilon x max(1, |p|) off the surface (epsilon 1e-9 by
     * default, a thousandth of this margin). An origin farther off is searched as usual (checked per ray).
     */
    private static final double OFFSET = 1e-6;

    /** Per primitive: its first cell in {@link #cell}, or -1 if it has none. */
    private final int[] firstCell;
    /** Per primitive with cells: the centre of the ball they cover and its radius squared, 4 doubles. */
    private final double[] covered;
    /**
     * Per cell, in one int so that a ray reads one place: its first slot in {@link #listed} times
     * 32 plus how many it lists (at most {@link #CAP}), or -1: fall back to the search.
     */
    private final int[] cell;
    /** The cells' lists of primitive numbers (numbers only: a large scene's lists stay small). */
    private final int[] listed;
    private final int[] unbounded, unboundedIndex;
    private final Shape[] unboundedKind;

    private LeavingCells(Aggregate searched, Builder b) {
        super(searched);
        this.firstCell = b.firstCell;
        this.covered = b.covered;
        this.cell = Arrays.copyOf(b.cell, b.cells);
        this.listed = Arrays.copyOf(b.listed, b.slots);
        int n = 0;
        int[] u = new int[primitives.count()];
        for (int q = 0; q < primitives.count(); q++) {
            if (!primitives.bounded(q)) {
                u[n++] = q;
            }
        }
        this.unbounded = Arrays.copyOf(u, n);
        this.unboundedKind = new Shape[n];
        this.unboundedIndex = new int[n];
        for (int i = 0; i < n; i++) {
            unboundedKind[i] = primitives.kind(primitives.kindOf(unbounded[i]));
            unboundedIndex[i] = primitives.indexOf(unbounded[i]);
        }
    }

    /** The filter in front of {@code searched}, or {@code searched} itself when no primitive has a cell to use. */
    public static Aggregate around(Aggregate searched) {
        Builder b = new Builder(searched.primitives());
        return b.cells > 0 ? new LeavingCells(searched, b) : searched;
    }

    /** Whether this ray, leaving primitive {@code skip}, is answered from a cell's list (not searched). */
    boolean usesCells(int skip, double ox, double oy, double oz, double dx, double dy, double dz) {
        return listing(skip, ox, oy, oz, dx, dy, dz) >= 0;
    }

    /**
     * The listing of the cell that answers this ray ({@link #cell}'s slot x 32 + count), or -1 when
     * the ray is searched: it skips no primitive with cells, starts outside the ball they cover, or
     * its cell falls back.
     */
    private int listing(int skip, double ox, double oy, double oz, double dx, double dy, double dz) {
        int first = skip >= 0 ? firstCell[skip] : -1;
        if (first < 0) {
            return -1;
        }
        int b = 4 * skip;
        double ex = ox - covered[b], ey = oy - covered[b + 1], ez = oz - covered[b + 2];
        return ex * ex + ey * ey + ez * ez <= covered[b + 3] ? cell[first + cellOf(dx, dy, dz)] : -1;
    }

    @Override
    public boolean nearest(double ox, double oy, double oz, double dx, double dy, double dz, double tMax, int skip,
                           int inside, Hit hit, TraversalStack stack) {
        int listing = listing(skip, ox, oy, oz, dx, dy, dz);
        if (listing >= 0) {
            return nearestListed(ox, oy, oz, dx, dy, dz, tMax, skip, listing >>> 5, listing & 31, hit);
        }
        return searched.nearest(ox, oy, oz, dx, dy, dz, tMax, skip, inside, hit, stack);
    }

    /** The unbounded primitives (but skip) and a cell's list, in that fixed order, as the hierarchy tests them. */
    private boolean nearestListed(double ox, double oy, double oz, double dx, double dy, double dz, double tMax,
                                  int skip, int from, int count, Hit hit) {
        double nearest = tMax;
        int found = Hit.NONE;
        for (int i = 0; i < unbounded.length; i++) {
            if (unbounded[i] != skip) {
                double t = unboundedKind[i].intersect(unboundedIndex[i], ox, oy, oz, dx, dy, dz, nearest);
                if (t < nearest) {
                    nearest = t;
                    found = unbounded[i];
                }
            }
        }
        for (int slot = from, end = from + count; slot < end; slot++) {
            double t = primitives.intersect(listed[slot], ox, oy, oz, dx, dy, dz, nearest);
            if (t < nearest) {
                nearest = t;
                found = listed[slot];
            }
        }
        if (found == Hit.NONE) {
            return false;
        }
        primitives.record(hit, found, nearest);
        return true;
    }

    /**
     * The cell of a direction: the face of its largest component (+x, -x, +y, -y, +z, -z), then the
     * other two components over the largest one's size, each in [-1, 1], cut into K steps.
     */
    static int cellOf(double dx, double dy, double dz) {
        double ax = Math.abs(dx), ay = Math.abs(dy), az = Math.abs(dz);
        int face;
        double major, u, v;
        if (ax >= ay && ax >= az) {
            face = dx > 0 ? 0 : 1;
            major = ax;
            u = dy;
            v = dz;
        } else if (ay >= az) {
            face = dy > 0 ? 2 : 3;
            major = ay;
            u = dx;
            v = dz;
        } else {
            face = dz > 0 ? 4 : 5;
            major = az;
            u = dx;
            v = dy;
        }
        double scale = 0.5 * K / major;
        int i = Math.min(K - 1, Math.max(0, (int) (u * scale + 0.5 * K)));
        int j = Math.min(K - 1, Math.max(0, (int) (v * scale + 0.5 * K)));
        return (face * K + i) * K + j;
    }

    @Override
    public String toString() {
        long fallBack = Arrays.stream(cell).filter(listing -> listing < 0).count();
        return "LeavingCells[" + cell.length / CELLS + " primitives with cells, " + fallBack + " of "
                + cell.length + " cells fall back, " + listed.length + " listed] in front of " + searched;
    }

    /** Works out the cells of every closed bounded primitive (see {@link CellCones} for the geometry). */
    private static final class Builder {

        final int[] firstCell;
        final double[] covered;
        int[] cell = new int[CELLS], listed = new int[64];
        int cells, slots;

        Builder(Primitives p) {
            int n = p.count();
            firstCell = new int[n];
            Arrays.fill(firstCell, -1);
            covered = new double[4 * n];
            double[] balls = new double[4 * n];
            double[] box = new double[6];
            for (int q = 0; q < n; q++) {
                if (p.bounded(q)) {
                    CellCones.ballOf(p, q, box, balls);
                }
            }
            CellCones cones = CellCones.INSTANCE;
            CellCones.Lists lists = new CellCones.Lists();
            BvhBuilder tree = new BvhBuilder(p, 4);
            double[] nodeBalls = nodeBalls(tree);
            int[] links = tree.links(), order = tree.order();
            int[] waiting = new int[tree.depth() + 2];
            for (int s = 0; s < n; s++) {
                if (!p.bounded(s) || !p.closed(s)) {
                    continue;
                }
                double cx = balls[4 * s], cy = balls[4 * s + 1], cz = balls[4 * s + 2];
                double r = balls[4 * s + 3];
                double reach = r + OFFSET * Math.max(1, Math.sqrt(cx * cx + cy * cy + cz * cz) + r);
                lists.reset();
                // the tree, nearer child first, leaving out nodes that only closed cells could reach
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
                        if (order[slot] != s) {
                            cones.reach(cx, cy, cz, reach, balls, 4 * order[slot], order[slot], lists);
                        }
                    }
                }
                add(s, cx, cy, cz, reach, lists);
            }
        }

        /** The ball around each node's box (it holds what the node's primitives hold). */
        private static double[] nodeBalls(BvhBuilder tree) {
            double[] box = tree.nodeBox();
            double[] ball = new double[4 * tree.nodeCount()];
            for (int node = 0; node < tree.nodeCount(); node++) {
                int b = 6 * node;
                double ex = 0.5 * (box[b + 3] - box[b]), ey = 0.5 * (box[b + 4] - box[b + 1]);
                double ez = 0.5 * (box[b + 5] - box[b + 2]);
                ball[4 * node] = 0.5 * (box[b] + box[b + 3]);
                ball[4 * node + 1] = 0.5 * (box[b + 1] + box[b + 4]);
                ball[4 * node + 2] = 0.5 * (box[b + 2] + box[b + 5]);
                ball[4 * node + 3] = Math.nextUp(Math.sqrt(ex * ex + ey * ey + ez * ez)) * (1 + 1e-12);
            }
            return ball;
        }

        private static double distance2(double[] balls, int node, double cx, double cy, double cz) {
            double ex = balls[4 * node] - cx, ey = balls[4 * node + 1] - cy, ez = balls[4 * node + 2] - cz;
            return ex * ex + ey * ey + ez * ez;
        }

        /** Appends S's cells, unless every one of them falls back. */
        private void add(int s, double cx, double cy, double cz, double reach, CellCones.Lists lists) {
            if (lists.open == 0) {
                return;
            }
            int[] counts = lists.counts;
            if (cells + CELLS > cell.length) {
                cell = Arrays.copyOf(cell, 2 * (cells + CELLS));
            }
            firstCell[s] = cells;
            covered[4 * s] = cx;
            covered[4 * s + 1] = cy;
            covered[4 * s + 2] = cz;
            covered[4 * s + 3] = reach * reach;
            for (int c = 0; c < CELLS; c++, cells++) {
                int count = counts[c];
                if (count > CAP) {
                    cell[cells] = -1;
                    continue;
                }
                if (slots + count > listed.length) {
                    listed = Arrays.copyOf(listed, 2 * (slots + count));
                }
                if (slots >= 1 << 26) {
                    throw new IllegalStateException("too many listed for a cell's int: " + slots);
                }
                cell[cells] = slots << 5 | count;
                System.arraycopy(lists.lists, c * CAP, listed, slots, count);
                Arrays.sort(listed, slots, slots + count); // in the primitives' order, whatever the tree's
                slots += count;
            }
        }
    }
}
