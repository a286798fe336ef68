package glint.accel;

import glint.geometry.Primitives;
import glint.geometry.Hit;
import java.util.Arrays;

/**
 * A filter in front of another aggregate for rays that leave a closed primitive on its outer side
 * (reflected off a metal or glass sphere, or leaving a glass one). For each closed bounded primitive
 * S a cube map of direction cells (6 faces of {@link AggregatePolicy#LEAVING_CELLS} squared) lists
 * the bounded primitives a ray starting within S's bounding ball, travelling in a direction of the
 * cell, could meet; such a ray tests the unbounded primitives and its cell's list instead of
 * searching. A cell that would list more than {@link AggregatePolicy#LEAVING_CELL_CAP} falls back
 * to the search, as does a ray whose origin is not within the ball the cells were worked out for
 * (S's bounding ball widened by {@link AggregatePolicy#SPAWN_MARGIN}). Worked out once, when the
 * scene is compiled. Shadow rays are searched as usual: answered from the cells, they took 0.90 to
 * 1.02 of the render CPU a frame on the default scene and glass-25 (4 runs), short of 5 %.
 */
public final class LeavingCells extends CellFilter {

    private static final int K = AggregatePolicy.LEAVING_CELLS;

    /** Per primitive: its first cell in {@link #cell}, or -1 if it has none. */
    private final int[] firstCell;
    /** Per primitive with cells: the centre of the ball they cover and its radius squared, 4 doubles. */
    private final double[] covered;

    private LeavingCells(Aggregate searched, CellMaps maps, int[] firstCell, double[] covered) {
        super(searched, maps);
        this.firstCell = firstCell;
        this.covered = covered;
    }

    /** The filter in front of {@code searched}, or {@code searched} itself when no primitive has a cell to use. */
    public static Aggregate around(Aggregate searched) {
        Primitives p = searched.primitives();
        int n = p.count();
        CellMaps maps = new CellMaps(p, K, AggregatePolicy.LEAVING_CELL_CAP);
        int[] firstCell = new int[n];
        Arrays.fill(firstCell, -1);
        double[] covered = new double[4 * n];
        double[] balls = maps.balls;
        for (int s = 0; s < n; s++) {
            if (!p.bounded(s) || !p.closed(s)) {
                continue;
            }
            double cx = balls[4 * s], cy = balls[4 * s + 1], cz = balls[4 * s + 2];
            double r = balls[4 * s + 3];
            // S's bounding ball widened by the spawn margin
            double reach = r + AggregatePolicy.SPAWN_MARGIN * Math.max(1, Math.sqrt(cx * cx + cy * cy + cz * cz) + r);
            firstCell[s] = maps.add(cx, cy, cz, reach, s);
            System.arraycopy(balls, 4 * s, covered, 4 * s, 3);
            covered[4 * s + 3] = reach * reach;
        }
        return maps.cells > 0 ? new LeavingCells(searched, maps, firstCell, covered) : searched;
    }

    /** Whether this ray, leaving primitive {@code skip}, is answered from a cell's list (not searched). */
    boolean usesCells(int skip, double ox, double oy, double oz, double dx, double dy, double dz) {
        return listing(skip, ox, oy, oz, dx, dy, dz) >= 0;
    }

    /**
     * The listing of the cell that answers this ray ({@link CellMaps#cell}), or -1 when the ray is
     * searched: it skips no primitive with cells, starts outside the ball they cover, or its cell
     * falls back.
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
            return nearestListed(ox, oy, oz, dx, dy, dz, tMax, skip, listing, hit);
        }
        return searched.nearest(ox, oy, oz, dx, dy, dz, tMax, skip, inside, hit, stack);
    }

    @Override
    public String toString() {
        return "LeavingCells[" + cell.length / (6 * K * K) + " primitives with cells, " + cellCounts()
                + "] in front of " + searched;
    }
}
