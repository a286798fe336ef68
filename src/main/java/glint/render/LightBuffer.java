package glint.render;

/**
 * The spheres that can shadow a point light, by direction: {@link ConeCells} around the light, a
 * cube of {@link #CELLS} x {@link #CELLS} cells a face, each listing the spheres whose cone of
 * directions (seen from the light) meets it. A shadow ray towards the light need only test the
 * spheres of the cell its direction falls in (Haines and Greenberg's light buffer, 1986). Built
 * with the compiled scene; immutable.
 *
 * <p>A shadow ray leaves from a point offset from the surface, so seen from the light its points
 * lie slightly off the line of its direction: by at most an angle whose sine is offset / (distance
 * from the light). Every cone is widened by {@link ConeCells#ANGLE_MARGIN}, which covers that for
 * offsets up to {@link #maxOffset}; rays offset further take the full test.
 */
final class LightBuffer {

    /** Cells along each side of a cube face. */
    static final int CELLS = 64;

    /** Shadow rays whose origin lies further than this from the surface point must take the full test. */
    final double maxOffset;
    /** Cell c lists cellSpheres[cellStart[c] .. cellStart[c + 1]). */
    final int[] cellStart;
    final int[] cellSpheres;

    private LightBuffer(double maxOffset, int[] cellStart, int[] cellSpheres) {
        this.maxOffset = maxOffset;
        this.cellStart = cellStart;
        this.cellSpheres = cellSpheres;
    }

    /** Room a buffer takes beyond its lists, in list entries: its cell index. */
    static final int CELL_INDEX_SIZE = ConeCells.indexSize(CELLS);

    /**
     * A light buffer for the point light at (x, y, z) over {@code count} spheres (cx, cy, cz, r
     * each), or null when its lists would hold more than {@code maxEntries} entries (spheres
     * crowding around the light): its shadow rays then take the full test.
     */
    static LightBuffer build(double[] spheres, int count, double x, double y, double z, long maxEntries) {
        int[] order = new int[count];
        for (int i = 0; i < count; i++) {
            order[i] = i;
        }
        ConeCells cells = ConeCells.build(spheres, order, count, 0, x, y, z, CELLS, maxEntries);
        if (cells == null) {
            return null;
        }
        return new LightBuffer(Math.sin(ConeCells.ANGLE_MARGIN) * cells.nearestSurface, cells.cellStart,
                cells.cellSpheres);
    }

    /** Entries in the buffer's lists. */
    int entries() {
        return cellSpheres.length;
    }

    /** The cell holding direction (vx, vy, vz) from the light (not necessarily unit length, not zero). */
    int cell(double vx, double vy, double vz) {
        return ConeCells.cell(vx, vy, vz, CELLS);
    }
}
