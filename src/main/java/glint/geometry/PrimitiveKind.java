package glint.geometry;

/**
 * One kind of primitive: all of a scene's primitives of that kind, in flat arrays (world space).
 * A kind is its bounds, its intersection and its surface at a hit, and for a closed kind a bounding
 * ball and which balls it reaches into (so that empty insides are found). The aggregates
 * ({@code glint.accel.Aggregate}) and the shading see primitives only through this interface, so
 * adding a kind means a class like {@link SphereKind} and its registration (docs/architecture.md).
 */
public interface PrimitiveKind {

    /** How many primitives of this kind. */
    int count();

    /**
     * Whether primitive i has finite bounds. Unbounded ones (planes) are tested by every ray; the
     * bounded ones go into the hierarchy.
     */
    boolean bounded(int i);

    /** Writes the box around primitive i (min x, y, z, max x, y, z) to {@code box} from {@code at}. */
    void bounds(int i, double[] box, int at);

    /**
     * Nearest t in (0, tMax) where the unit ray from o along d meets primitive i, or
     * {@link Intersect#MISS}.
     */
    double intersect(int i, double ox, double oy, double oz, double dx, double dy, double dz, double tMax);

    /**
     * For the rays r in [first, end) from the common origin o along unit (dx[r], dy[r], dz[r]): where
     * primitive i is met before nearestT[r], sets nearestT[r] to that distance and
     * nearestPrimitive[r] to {@code number}. The same distances as {@link #intersect} ray by ray; a
     * kind may override it to work out what depends on the origin alone once.
     */
    default void nearestFromOrigin(int i, int number, double ox, double oy, double oz, double[] dx, double[] dy,
                                   double[] dz, int first, int end, double[] nearestT, int[] nearestPrimitive) {
        for (int r = first; r < end; r++) {
            double t = intersect(i, ox, oy, oz, dx[r], dy[r], dz[r], nearestT[r]);
            if (t < nearestT[r]) {
                nearestT[r] = t;
                nearestPrimitive[r] = number;
            }
        }
    }

    /**
     * Fills the hit's surface for primitive i near point p (p from the ray, carrying t's rounding):
     * the point moved onto the surface, and the unit outward normal there.
     */
    void surfaceAt(int i, double px, double py, double pz, Hit hit);

    /**
     * Where a ray inside primitive i meets its surface again, for a kind that knows it in closed
     * form: the ray leaves surface point p along unit u into the primitive, at cosine
     * {@code cosInside} to the inward normal there, and rays leaving the surface start
     * {@code offset} off it. Writes to {@code end} the chord's length (t), the point where it ends
     * and the unit outward normal there, and returns the cosine between u and that normal; returns
     * NaN, leaving {@code end} alone, where the kind has no closed form or the primitive is too small
     * for an offset ray to start inside it (the caller then searches as for any ray). Asked only of
     * closed kinds, for primitives nothing else reaches into.
     */
    default double chordInside(int i, double px, double py, double pz, double ux, double uy, double uz,
                               double cosInside, double offset, Hit end) {
        return Double.NaN;
    }

    /**
     * Writes a ball that holds primitive i (centre x, y, z, radius) to {@code ball}; asked only of
     * closed kinds, whose inside it must hold.
     */
    void boundingBall(int i, double[] ball);

    /**
     * Whether primitive i may have points strictly inside the ball of centre c and radius r: true
     * whenever it has (a kind may answer true when unsure); touching the ball's surface, to
     * rounding, does not count.
     */
    boolean reachesInto(int i, double cx, double cy, double cz, double r);

    /**
     * Whether a ray leaving primitive i into its inside (against the outward normal) can meet it
     * again: true for a closed shape (a sphere's far side), false for a flat one. A ray leaving on
     * the outer side never meets the primitive it leaves (every kind is convex or flat).
     */
    boolean closed();

    /**
     * Whether {@link #reachesInto} errs by less than 1e-9 of a ball's radius and of its distance from
     * the origin, as a plane's single test |n.c - d| < r does: then its answer for a ball widened by
     * that much around a group of balls holds for each of them, and the scene compiler asks an
     * unbounded primitive of such a kind about groups of closed primitives before asking each
     * ({@code EmptyInteriors}). False by default: each is asked.
     */
    default boolean reachesIntoWithinRounding() {
        return false;
    }
}
