package glint.accel;

import glint.geometry.Hit;

/**
 * A filter in front of another aggregate for shadow rays towards one point light L: a cube map of
 * direction cells around L lists the bounded primitives a ray starting within the ball (L, reach),
 * travelling in a direction of the cell, could meet. A shadow ray from o along d up to tMax whose
 * end o + tMax d lies in that ball is that ray run backwards (from its end along -d), so it tests
 * the unbounded primitives and the list of the cell of -d instead of searching. A surface's shadow
 * ray ends within its spawn offset of L (it starts at p + offset n with tMax = |L - p|), so the
 * reach covers that offset; a ray ending farther off, or whose cell would list more than its cap,
 * is searched as usual (checked per ray). Nearest-hit queries go straight to the aggregate behind.
 */
public final class LightCells extends CellFilter {

    /**
     * The longest shadow ray the cells answer, relative to the reach: the ray's end, computed in
     * doubles, is then off by well under a thousandth of the reach (a few rounding steps of
     * |o| + tMax), which the cells, worked out for twice the reach, cover. A longer ray could have its
     * computed end within reach while the ray itself passes far from the light; it is searched.
     * With the default epsilon every surface that can use the cells is this close anyway.
     */
    static final double LONGEST = 1e9;

    private final double lx, ly, lz, reach2, longest;

    private LightCells(Aggregate searched, CellMaps maps, double lx, double ly, double lz, double reach) {
        super(searched, maps);
        this.lx = lx;
        this.ly = ly;
        this.lz = lz;
        this.reach2 = reach * reach;
        this.longest = LONGEST * reach;
    }

    /**
     * The filter for shadow rays towards the point light at (lx, ly, lz), of k x k cells a cube
     * face listing at most {@code cap} primitives each, in front of {@code searched}; or
     * {@code searched} itself when every cell would fall back.
     */
    public static Aggregate around(Aggregate searched, double lx, double ly, double lz, int k, int cap) {
        CellMaps maps = new CellMaps(searched.primitives(), k, cap);
        // the spawn margin around the light: with the default epsilon, every surface point up to a
        // thousand times max(1, |L|) from the origin ends its shadow ray within it
        double reach = AggregatePolicy.SPAWN_MARGIN * Math.max(1, Math.sqrt(lx * lx + ly * ly + lz * lz));
        return maps.add(lx, ly, lz, 2 * reach, Hit.NONE) < 0 ? searched
                : new LightCells(searched, maps, lx, ly, lz, reach);
    }

    /** Whether this shadow ray is answered from a cell's list (not searched). */
    boolean usesCells(double ox, double oy, double oz, double dx, double dy, double dz, double tMax) {
        return listing(ox, oy, oz, dx, dy, dz, tMax) >= 0;
    }

    /**
     * The listing of the cell of -d when the ray is at most {@link #LONGEST} reaches long and ends
     * within reach of the light, else -1.
     */
    private int listing(double ox, double oy, double oz, double dx, double dy, double dz, double tMax) {
        double ex = ox + tMax * dx - lx, ey = oy + tMax * dy - ly, ez = oz + tMax * dz - lz;
        return tMax <= longest && ex * ex + ey * ey + ez * ez <= reach2 ? cell[cellOf(-dx, -dy, -dz)] : -1;
    }

    @Override
    public boolean nearest(double ox, double oy, double oz, double dx, double dy, double dz, double tMax, int skip,
                           int inside, Hit hit, TraversalStack stack) {
        return searched.nearest(ox, oy, oz, dx, dy, dz, tMax, skip, inside, hit, stack);
    }

    @Override
    public double transmittance(double ox, double oy, double oz, double dx, double dy, double dz, double tMax,
                                int skip, double[] pass, TraversalStack stack) {
        int listing = listing(ox, oy, oz, dx, dy, dz, tMax);
        if (listing >= 0) {
            return transmittanceListed(ox, oy, oz, dx, dy, dz, tMax, skip, listing, pass);
        }
        return searched.transmittance(ox, oy, oz, dx, dy, dz, tMax, skip, pass, stack);
    }

    @Override
    public String toString() {
        return "LightCells[light (" + lx + ", " + ly + ", " + lz + "), " + cellCounts() + "] in front of " + searched;
    }
}
