package glint.render;

/**
 * The spheres that can shadow a point light, by direction: a cube around the light, each face
 * split into CELLS x CELLS cells, each cell listing the spheres whose cone of directions (seen from
 * the light) meets it. A shadow ray towards the light need only test the spheres of the cell its
 * direction falls in (Haines and Greenberg's light buffer, 1986). Built with the compiled scene;
 * immutable.
 *
 * <p>A shadow ray leaves from a point offset from the surface, so seen from the light its points
 * lie slightly off the line of its direction: by at most an angle whose sine is offset / (distance
 * from the light). Every cone is widened by {@link #ANGLE_MARGIN}, which covers that for offsets
 * up to {@link #maxOffset}; rays offset further take the full test.
 */
final class LightBuffer {

    /** Cells along each side of a cube face. */
    static final int CELLS = 64;
    /** Extra half-angle of every sphere's cone of directions, radians. */
    static final double ANGLE_MARGIN = 1e-4;
    private static final int FACES = 6;

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
    static final int CELL_INDEX_SIZE = FACES * CELLS * CELLS + 1;

    /**
     * A light buffer for the point light at (x, y, z) over {@code count} spheres (cx, cy, cz, r
     * each), or null when its lists would hold more than {@code maxEntries} entries (spheres
     * crowding around the light): its shadow rays then take the full test.
     */
    static LightBuffer build(double[] spheres, int count, double x, double y, double z, long maxEntries) {
        int cells = FACES * CELLS * CELLS;
        int[] rect = new int[4 * FACES * count]; // per sphere and face: first and last cell column and row, or -1
        double nearest = Double.POSITIVE_INFINITY;
        double[] range = new double[4];
        for (int i = 0; i < count; i++) {
            nearest = Math.min(nearest, coverSphere(spheres, i, x, y, z, rect, range));
        }
        // count each cell's spheres, then place them, in sphere order
        int[] fill = new int[cells];
        for (int i = 0; i < count; i++) {
            addToCells(rect, i, fill, null);
        }
        int[] cellStart = new int[cells + 1];
        long entries = 0;
        for (int c = 0; c < cells; c++) {
            entries += fill[c];
            if (entries > maxEntries) {
                return null;
            }
            cellStart[c + 1] = (int) entries;
            fill[c] = cellStart[c];
        }
        int[] cellSpheres = new int[cellStart[cells]];
        for (int i = 0; i < count; i++) {
            addToCells(rect, i, fill, cellSpheres);
        }
        return new LightBuffer(Math.sin(ANGLE_MARGIN) * nearest, cellStart, cellSpheres);
    }

    /** Entries in the buffer's lists. */
    int entries() {
        return cellSpheres.length;
    }

    /**
     * Finds the cells of every face that sphere i's widened cone meets, into rect; returns the
     * distance from the light to the sphere's surface, or infinity when the cone holds every
     * direction (the light is inside or nearly touching the sphere).
     */
    private static double coverSphere(double[] spheres, int i, double lightX, double lightY, double lightZ,
                                      int[] rect, double[] range) {
        double[] centre = {spheres[4 * i] - lightX, spheres[4 * i + 1] - lightY, spheres[4 * i + 2] - lightZ};
        double radius = spheres[4 * i + 3];
        double distance = Math.sqrt(centre[0] * centre[0] + centre[1] * centre[1] + centre[2] * centre[2]);
        // asin(r / d + margin) >= asin(r / d) + margin: the cone of this radius is wide enough
        double widened = radius + ANGLE_MARGIN * distance;
        boolean everywhere = !(distance > widened * (1 + 1e-9));
        for (int face = 0; face < FACES; face++) {
            int axis = face >> 1;
            double along = (face & 1) == 0 ? centre[axis] : -centre[axis];
            int at = 4 * (FACES * i + face);
            if (everywhere) {
                setRect(rect, at, 0, CELLS - 1, 0, CELLS - 1);
                continue;
            }
            if (along < -widened) {
                rect[at] = -1; // wholly behind the face
                continue;
            }
            // infinite ranges, and so the whole face, where the cone crosses the face's plane
            ScreenRange.of(centre[(axis + 1) % 3], along, widened, range, 0);
            ScreenRange.of(centre[(axis + 2) % 3], along, widened, range, 2);
            if (range[1] < -1 || range[0] > 1 || range[3] < -1 || range[2] > 1) {
                rect[at] = -1;
                continue;
            }
            setRect(rect, at, cellOf(range[0]), cellOf(range[1]), cellOf(range[2]), cellOf(range[3]));
        }
        return everywhere ? Double.POSITIVE_INFINITY : distance - radius;
    }

    private static void setRect(int[] rect, int at, int u0, int u1, int v0, int v1) {
        rect[at] = u0;
        rect[at + 1] = u1;
        rect[at + 2] = v0;
        rect[at + 3] = v1;
    }

    /**
     * For each cell the sphere's cone meets: without a list, counts it in fill[cell]; with one,
     * writes the sphere at list[fill[cell]] and moves fill[cell] on.
     */
    private static void addToCells(int[] rect, int sphere, int[] fill, int[] list) {
        for (int face = 0; face < FACES; face++) {
            int at = 4 * (FACES * sphere + face);
            if (rect[at] < 0) {
                continue;
            }
            for (int v = rect[at + 2]; v <= rect[at + 3]; v++) {
                for (int u = rect[at]; u <= rect[at + 1]; u++) {
                    int cell = (face * CELLS + v) * CELLS + u;
                    if (list != null) {
                        list[fill[cell]] = sphere;
                    }
                    fill[cell]++;
                }
            }
        }
    }

    /** The cell column (or row) of face coordinate s in [-1, 1]; coordinates beyond go to the edge cells. */
    private static int cellOf(double s) {
        int cell = (int) Math.floor((s + 1) * (CELLS / 2.0));
        return Math.max(0, Math.min(CELLS - 1, cell));
    }

    /**
     * The cell holding direction (vx, vy, vz) from the light (not necessarily unit length, not zero):
     * its face is that of its largest component, its coordinates the other two divided by that one.
     */
    int cell(double vx, double vy, double vz) {
        double ax = Math.abs(vx), ay = Math.abs(vy), az = Math.abs(vz);
        int face;
        double major, u, v;
        if (ax >= ay && ax >= az) {
            face = vx >= 0 ? 0 : 1;
            major = ax;
            u = vy;
            v = vz;
        } else if (ay >= az) {
            face = vy >= 0 ? 2 : 3;
            major = ay;
            u = vz;
            v = vx;
        } else {
            face = vz >= 0 ? 4 : 5;
            major = az;
            u = vx;
            v = vy;
        }
        double scale = (CELLS / 2.0) / major;
        int column = Math.min(CELLS - 1, Math.max(0, (int) (u * scale + CELLS / 2.0)));
        int row = Math.min(CELLS - 1, Math.max(0, (int) (v * scale + CELLS / 2.0)));
        return (face * CELLS + row) * CELLS + column;
    }
}
