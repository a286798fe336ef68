package glint.geometry;

/**
 * Ray-shape intersection in double precision, written to stay right where the textbook formulas
 * fail. Directions are unit length; a miss is {@link Double#POSITIVE_INFINITY}.
 */
public final class Intersect {

    public static final double MISS = Double.POSITIVE_INFINITY;

    private Intersect() {
    }

    /**
     * Nearest t in (0, tMax) where the ray meets the sphere, else {@link #MISS}. Follows Ray Tracing
     * Gems ch. 7: the discriminant is r^2 - |f - (f.d) d|^2 (no cancellation between two large
     * squares), and the root that would subtract nearly equal numbers is taken as c / q instead.
     * The cheap rejections (sphere behind the ray, closest approach beyond tMax) run before any
     * square root.
     */
    public static double sphereBefore(double cx, double cy, double cz, double radius,
                                      double ox, double oy, double oz, double dx, double dy, double dz,
                                      double tMax) {
        double fx = ox - cx, fy = oy - cy, fz = oz - cz;
        return sphereFrom(fx, fy, fz, fx * fx + fy * fy + fz * fz - radius * radius, radius, dx, dy, dz, tMax);
    }

    /**
     * The sphere test from precomputed origin terms: f = origin - centre and c = f.f - r^2 (shared
     * by every camera ray of a frame).
     */
    public static double sphereFrom(double fx, double fy, double fz, double c, double radius,
                             double dx, double dy, double dz, double tMax) {
        double b = -(fx * dx + fy * dy + fz * dz); // distance along the ray to the closest approach
        if ((c > 0 && b <= 0) || b - radius >= tMax) {
            return MISS;
        }
        double hx = fx + b * dx, hy = fy + b * dy, hz = fz + b * dz;
        double discriminant = radius * radius - (hx * hx + hy * hy + hz * hz);
        if (discriminant < 0) {
            return MISS;
        }
        double root = Math.sqrt(discriminant);
        double t;
        if (c > 0) {
            t = c / (b + root);             // outside, approaching: the near root
        } else if (b >= 0) {
            t = b + root;                   // inside: the far root
        } else {
            t = c / (b - root);             // inside, moving away from the centre
        }
        return t > 0 && t < tMax ? t : MISS;
    }

    /**
     * Nearest t in (0, tMax) where the ray meets the plane n.p = offset, else {@link #MISS}. A ray
     * parallel to the plane (or lying in it) misses; a nearly parallel one hits far away, never at
     * NaN. Divides only for a hit.
     */
    public static double planeBefore(double nx, double ny, double nz, double offset,
                                     double ox, double oy, double oz, double dx, double dy, double dz,
                                     double tMax) {
        return planeFrom(offset - (nx * ox + ny * oy + nz * oz), nx * dx + ny * dy + nz * dz, tMax);
    }

    /** The plane test from numerator = offset - n.o and denominator = n.d. */
    public static double planeFrom(double numerator, double denominator, double tMax) {
        // t = numerator / denominator lies in (0, tMax) iff both have one sign and |num| < tMax |den|
        if (!(numerator * denominator > 0) || !(Math.abs(numerator) < tMax * Math.abs(denominator))) {
            return MISS;
        }
        return numerator / denominator;
    }
}
