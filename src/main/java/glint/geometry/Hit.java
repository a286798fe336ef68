package glint.geometry;

/**
 * Scratch value of one ray's nearest hit: which primitive (its kind, its index within the kind, and
 * its number in the scene), how far along the ray, and once {@link Primitives#describe} has run,
 * the point on the surface and the unit outward normal there (world space). One per path vertex;
 * nothing else writes it.
 */
public final class Hit {

    /** A primitive number no primitive has: "skip nothing". */
    public static final int NONE = -1;

    /** Distance along the ray. */
    public double t;
    /** The primitive's number in the scene (0 .. count - 1). */
    public int primitive = NONE;
    /** The primitive's kind (an index into {@link Primitives#kinds}) and its index within the kind. */
    public int kind, index;
    /** The hit point, moved onto the surface. */
    public double px, py, pz;
    /** The unit outward normal at the hit point. */
    public double nx, ny, nz;
}
