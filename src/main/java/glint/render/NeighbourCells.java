package glint.render;

import java.util.Arrays;
import java.util.Comparator;

/**
 * The spheres a ray leaving a sphere on its outer side can meet, by direction: {@link ConeCells}
 * around the sphere's centre. A ray that starts within distance {@code reach} of the centre and
 * meets sphere j has a direction within the cone, seen from the centre, of sphere j grown by
 * {@code reach} (move the ray's start to the centre and the sphere by as much), so it need test only
 * the spheres its direction's cell lists. Each cell lists them nearest first, with a distance no ray
 * from within reach can meet them before: once a hit is nearer than that, the rest of the list can
 * be left. Built with the compiled scene; immutable.
 */
final class NeighbourCells {

    /**
     * Cells along each side of a cube face. Each neighbour's cone is grown by the reach (about the
     * radius), so it spans many cells at any size: finer cells list nearly the same spheres per ray,
     * and at 4 x 4 a scene's lists stay small enough to stay in cache (glass-25: 0.37 MB against
     * 5.7 MB at 16 x 16, for the same instructions a frame and a seventh fewer cycles).
     */
    static final int CELLS = 4;

    /** Room a buffer takes beyond its lists, in list entries: its cell index. */
    static final int CELL_INDEX_SIZE = ConeCells.indexSize(CELLS);

    /** Cell c lists cellSpheres[cellStart[c] .. cellStart[c + 1]), each nearer than the next. */
    final int[] cellStart;
    final int[] cellSpheres;
    /** Per list entry, a distance along the ray before which it cannot meet that sphere. */
    final double[] cellNear;

    private NeighbourCells(int[] cellStart, int[] cellSpheres, double[] cellNear) {
        this.cellStart = cellStart;
        this.cellSpheres = cellSpheres;
        this.cellNear = cellNear;
    }

    /**
     * The cells around sphere i of {@code count} (cx, cy, cz, r each), for rays starting within
     * {@code reach} (at least its radius) of its centre, listing every other sphere; null when the
     * lists would hold more than {@code maxEntries} entries.
     */
    static NeighbourCells build(double[] spheres, int count, int i, double reach, long maxEntries) {
        double x = spheres[4 * i], y = spheres[4 * i + 1], z = spheres[4 * i + 2];
        double[] near = new double[count];
        Integer[] others = new Integer[count - 1];
        for (int j = 0, n = 0; j < count; j++) {
            if (j != i) {
                others[n++] = j;
                near[j] = nearestStart(spheres, j, x, y, z, reach);
            }
        }
        Arrays.sort(others, Comparator.comparingDouble(j -> near[j]));
        int[] order = new int[count - 1];
        for (int j = 0; j < order.length; j++) {
            order[j] = others[j];
        }
        ConeCells cells = ConeCells.build(spheres, order, order.length, reach, x, y, z, CELLS, maxEntries);
        if (cells == null) {
            return null;
        }
        double[] cellNear = new double[cells.entries()];
        for (int e = 0; e < cellNear.length; e++) {
            cellNear[e] = near[cells.cellSpheres[e]];
        }
        return new NeighbourCells(cells.cellStart, cells.cellSpheres, cellNear);
    }

    /**
     * A distance along any ray starting within {@code reach} of (x, y, z) before which it cannot meet
     * sphere j: |centre - (x, y, z)| - r - reach, less a margin far above the rounding of the sphere
     * test.
     */
    private static double nearestStart(double[] spheres, int j, double x, double y, double z, double reach) {
        double cx = spheres[4 * j] - x, cy = spheres[4 * j + 1] - y, cz = spheres[4 * j + 2] - z;
        double distance = Math.sqrt(cx * cx + cy * cy + cz * cz), radius = spheres[4 * j + 3];
        return distance - radius - reach - 1e-9 * (distance + radius + reach + 1);
    }

    /** Entries in the lists. */
    int entries() {
        return cellSpheres.length;
    }

    /** The cell holding direction (vx, vy, vz) from the sphere's centre (not necessarily unit length, not zero). */
    int cell(double vx, double vy, double vz) {
        return ConeCells.cell(vx, vy, vz, CELLS);
    }
}
