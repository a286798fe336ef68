package glint.study;

/**
 * Ray-sphere tests in single precision, the study subjects beside Glint's double-precision
 * {@link glint.geometry.Intersect}: every operation rounds to float, as on a GPU or in a float
 * tracer. Directions need not be unit length (a float direction seldom is). A miss is
 * {@link Float#POSITIVE_INFINITY}; t is in units of the given direction.
 */
public final class FloatSphere {

    public static final float MISS = Float.POSITIVE_INFINITY;

    private FloatSphere() {
    }

    /** The textbook quadratic: disc = (d.s)^2 - (d.d)(s.s - r^2), t = (d.s -+ sqrt(disc)) / d.d. */
    public static float naive(float cx, float cy, float cz, float radius,
                              float ox, float oy, float oz, float dx, float dy, float dz) {
        float sx = cx - ox, sy = cy - oy, sz = cz - oz;
        float ds = dx * sx + dy * sy + dz * sz;
        float dd = dx * dx + dy * dy + dz * dz;
        float disc = ds * ds - dd * (sx * sx + sy * sy + sz * sz - radius * radius);
        if (disc < 0) {
            return MISS;
        }
        float root = (float) Math.sqrt(disc);
        float t0 = (ds - root) / dd;
        float t1 = (ds + root) / dd;
        if (t0 > 0) {
            return t0;
        }
        return t1 > 0 ? t1 : MISS;
    }

    /**
     * Ray Tracing Gems ch. 7 for a direction of any length: with f = o - c, b = -f.d and a = d.d the
     * discriminant is a (r^2 - |f + (b/a) d|^2) (the squared distance from the centre to the line,
     * no cancellation of two large squares) and the nearer root c / q, q = b + sign(b) sqrt(disc)
     * (no cancellation of b and the root).
     */
    public static float stable(float cx, float cy, float cz, float radius,
                               float ox, float oy, float oz, float dx, float dy, float dz) {
        float fx = ox - cx, fy = oy - cy, fz = oz - cz;
        float a = dx * dx + dy * dy + dz * dz;
        float b = -(fx * dx + fy * dy + fz * dz);
        float k = b / a;
        float hx = fx + k * dx, hy = fy + k * dy, hz = fz + k * dz;
        float r2 = radius * radius;
        float disc = a * (r2 - (hx * hx + hy * hy + hz * hz));
        if (disc < 0) {
            return MISS;
        }
        float q = b + Math.copySign((float) Math.sqrt(disc), b);
        if (q == 0) {
            return MISS;
        }
        float c = fx * fx + fy * fy + fz * fz - r2;
        float t0 = c / q;
        float t1 = q / a;
        float near = Math.min(t0, t1), far = Math.max(t0, t1);
        if (near > 0) {
            return near;
        }
        return far > 0 ? far : MISS;
    }
}
