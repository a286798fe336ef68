package glint.render;

/**
 * Directions from a point, split into cells, each listing the spheres whose cone of directions
 * (seen from the point) meets it: the directions form a cube around the point, each face split into
 * {@code side} x {@code side} cells. A ray from the point need only test the spheres of the cell its
 * direction falls in. {@link LightBuffer} lists, around a light, the spheres that can shadow it;
 * {@link NeighbourCells} lists, around a sphere, the spheres a ray leaving it can meet. Immutable.
 */
final class ConeCells {

    /** Extra half-angle of every sphere's cone of directions, radians. */
    static final double ANGLE_MARGIN = 1e-4;
    static final int FACES = 6;

    /** Cell c lists spheres[cellStart[c] .. cellStart[c + 1]), in the order the spheres were given. */
    final int[] cellStart;
    final int[] cellSpheres;
    /**
     * The distance from the point to the nearest sphere's surface (before any widening), or
     * infinity when a cone holds every direction.
     */
    final double nearestSurface;

    private ConeCells(int[] cellStart, int[] cellSpheres, double nearestSurface) {
        this.cellStart = cellStart;
        this.cellSpheres = cellSpheres;
        this.nearestSurface = nearestSurface;
    }

    /** Room the cells take beyond their lists, in list entries: the cell index. */
    static int indexSize(int side) {
        return FACES * side * side + 1;
    }

    /**
     * The cells around point (x, y, z) for spheres order[0, n) (cx, cy, cz, r each in
     * {@code spheres}), each sphere's radius grown by {@code grow}, listed in that order; null when
     * the lists would hold more than {@code maxEntries} entries.
     */
    static ConeCells build(double[] spheres, int[] order, int n, double grow, double x, double y, double z,
                           int side, long maxEntries) {
        int cells = FACES * side * side;
        int[] rect = new int[4 * FACES * n]; // per listed sphere and face: first and last cell column and row, or -1
        double nearest = Double.POSITIVE_INFINITY;
        double[] range = new double[4];
        for (int j = 0; j < n; j++) {
            nearest = Math.min(nearest, coverSphere(spheres, order[j], grow, x, y, z, side, rect, j, range));
        }
        // count each cell's spheres, then place them, in the given order
        int[] fill = new int[cells];
        for (int j = 0; j < n; j++) {
            addToCells(rect, j, order[j], side, fill, null);
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
        for (int j = 0; j < n; j++) {
            addToCells(rect, j, order[j], side, fill, cellSpheres);
        }
        return new ConeCells(cellStart, cellSpheres, nearest);
    }

    /** Entries in the lists. */
    int entries() {
        return cellSpheres.length;
    }

    /**
     * Finds the cells of every face that sphere i's widened cone meets, into rect at slot j; returns
     * the distance from the point to the sphere's surface, or infinity when the cone holds every
     * direction (the point is inside or nearly touching the grown sphere).
     */
    private static double coverSphere(double[] spheres, int i, double grow, double x, double y, double z, int side,
                                      int[] rect, int j, double[] range) {
        double[] centre = {spheres[4 * i] - x, spheres[4 * i + 1] - y, spheres[4 * i + 2] - z};
        double radius = spheres[4 * i + 3];
        double distance = Math.sqrt(centre[0] * centre[0] + centre[1] * centre[1] + centre[2] * centre[2]);
        // asin(r / d + margin) >= asin(r / d) + margin: the cone of this radius is wide enough
        double widened = radius + grow + ANGLE_MARGIN * distance;
        boolean everywhere = !(distance > widened * (1 + 1e-9));
        for (int face = 0; face < FACES; face++) {
            int axis = face >> 1;
            double along = (face & 1) == 0 ? centre[axis] : -centre[axis];
            int at = 4 * (FACES * j + face);
            if (everywhere) {
                setRect(rect, at, 0, side - 1, 0, side - 1);
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
            setRect(rect, at, cellOf(range[0], side), cellOf(range[1], side), cellOf(range[2], side),
                    cellOf(range[3], side));
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
     * For each cell the cone in slot j of rect meets: without a list, counts it in fill[cell]; with
     * one, writes the sphere at list[fill[cell]] and moves fill[cell] on.
     */
    private static void addToCells(int[] rect, int j, int sphere, int side, int[] fill, int[] list) {
        for (int face = 0; face < FACES; face++) {
            int at = 4 * (FACES * j + face);
            if (rect[at] < 0) {
                continue;
            }
            for (int v = rect[at + 2]; v <= rect[at + 3]; v++) {
                for (int u = rect[at]; u <= rect[at + 1]; u++) {
                    int cell = (face * side + v) * side + u;
                    if (list != null) {
                        list[fill[cell]] = sphere;
                    }
                    fill[cell]++;
                }
            }
        }
    }

    /** The cell column (or row) of face coordinate s in [-1, 1]; coordinates beyond go to the edge cells. */
    private static int cellOf(double s, int side) {
        int cell = (int) Math.floor((s + 1) * (side / 2.0));
        return Math.max(0, Math.min(side - 1, cell));
    }

    /**
     * The cell holding direction (vx, vy, vz) among {@code side} x {@code side} a face: its face is
     * that of its largest component, its coordinates the other two divided by that one.
     */
    static int cell(double vx, double vy, double vz, int side) {
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
        double scale = (side / 2.0) / major;
        int column = Math.min(side - 1, Math.max(0, (int) (u * scale + side / 2.0)));
        int row = Math.min(side - 1, Math.max(0, (int) (v * scale + side / 2.0)));
        return (face * side + row) * side + column;
    }
}
