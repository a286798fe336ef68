package glint.render;

/**
 * Ray-shape intersection in double precision, written to stay right where the textbook formulas
 * fail. Directions are unit length; a miss is {@link Double#POSITIVE_INFINITY}.
 */
public final class Intersect {

    public static final double MISS = Double.POSITIVE_INFINITY;

    private Intersect() {
    }

    /**
     * Nearest t > 0 where the ray meets the sphere. Follows Ray Tracing Gems ch. 7: the
     * discriminant is r^2 - |f - (f.d) d|^2 (no cancellation between two large squares), and the
     * smaller root is c / q rather than (b - sqrt(disc)) / 2a (no cancellation between b and sqrt).
     */
    public static double sphere(double cx, double cy, double cz, double radius,
                                double ox, double oy, double oz, double dx, double dy, double dz) {
        double fx = ox - cx, fy = oy - cy, fz = oz - cz;
        double b = -(fx * dx + fy * dy + fz * dz);
        double hx = fx + b * dx, hy = fy + b * dy, hz = fz + b * dz;
        double r2 = radius * radius;
        double discriminant = r2 - (hx * hx + hy * hy + hz * hz);
        if (discriminant < 0) {
            return MISS;
        }
        double q = b + Math.copySign(Math.sqrt(discriminant), b);
        if (q == 0) {
            return MISS;
        }
        double c = fx * fx + fy * fy + fz * fz - r2;
        double t0 = c / q;
        double t1 = q;
        double near = Math.min(t0, t1);
        double far = Math.max(t0, t1);
        if (near > 0) {
            return near;
        }
        return far > 0 ? far : MISS;
    }

    /**
     * The textbook sphere test: the quadratic in t with the usual root formula, as in the 2020
     * report. Kept only to measure how it fails; the renderer never uses it.
     */
    public static double sphereNaive(double cx, double cy, double cz, double radius,
                                     double ox, double oy, double oz, double dx, double dy, double dz) {
        double sx = cx - ox, sy = cy - oy, sz = cz - oz;
        double ds = dx * sx + dy * sy + dz * sz;
        double dd = dx * dx + dy * dy + dz * dz;
        double discriminant = ds * ds - dd * (sx * sx + sy * sy + sz * sz - radius * radius);
        if (discriminant < 0) {
            return MISS;
        }
        double root = Math.sqrt(discriminant);
        double t0 = (ds - root) / dd;
        double t1 = (ds + root) / dd;
        if (t0 > 0) {
            return t0;
        }
        return t1 > 0 ? t1 : MISS;
    }

    /**
     * Nearest t > 0 where the ray meets the plane n.p = offset. A ray parallel to the plane (or
     * lying in it) misses; a nearly parallel one hits far away, never at NaN.
     */
    public static double plane(double nx, double ny, double nz, double offset,
                               double ox, double oy, double oz, double dx, double dy, double dz) {
        double denominator = nx * dx + ny * dy + nz * dz;
        if (denominator == 0) {
            return MISS;
        }
        double t = (offset - (nx * ox + ny * oy + nz * oz)) / denominator;
        return t > 0 && t < MISS ? t : MISS;
    }
}
