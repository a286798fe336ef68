package glint.study;

import glint.geometry.Intersect;

/** The four ray-sphere tests the stability study compares: two formulas, two precisions. */
public enum SphereMethod {

    NAIVE_FLOAT("naive quadratic, float", true),
    STABLE_FLOAT("stable form (RTG ch. 7), float", true),
    NAIVE_DOUBLE("naive quadratic, double", false),
    STABLE_DOUBLE("stable form, double (Glint)", false);

    private final String label;
    private final boolean single;

    SphereMethod(String label, boolean single) {
        this.label = label;
        this.single = single;
    }

    public String label() {
        return label;
    }

    /** True for the single-precision methods, which see every input rounded to float. */
    public boolean isFloat() {
        return single;
    }

    /** The input as this method sees it: rounded to float for the float methods. */
    public double input(double v) {
        return single ? (float) v : v;
    }

    /**
     * Nearest t > 0, or {@link Double#POSITIVE_INFINITY} for a miss. Arguments are taken as they
     * are; call {@link #input} first so that the exact answer is computed from the same values.
     */
    public double nearestT(double cx, double cy, double cz, double r, double ox, double oy, double oz,
                           double dx, double dy, double dz) {
        return switch (this) {
            case NAIVE_FLOAT -> widen(FloatSphere.naive((float) cx, (float) cy, (float) cz, (float) r,
                    (float) ox, (float) oy, (float) oz, (float) dx, (float) dy, (float) dz));
            case STABLE_FLOAT -> widen(FloatSphere.stable((float) cx, (float) cy, (float) cz, (float) r,
                    (float) ox, (float) oy, (float) oz, (float) dx, (float) dy, (float) dz));
            case NAIVE_DOUBLE -> sphereNaive(cx, cy, cz, r, ox, oy, oz, dx, dy, dz);
            case STABLE_DOUBLE -> Intersect.sphereBefore(cx, cy, cz, r, ox, oy, oz, dx, dy, dz, Intersect.MISS);
        };
    }

    private static double widen(float t) {
        return t == FloatSphere.MISS ? Double.POSITIVE_INFINITY : t;
    }

    /**
     * The textbook sphere test: the quadratic in t with the usual root formula, as in the 2020
     * report, to measure how it fails; the renderer never uses it.
     */
    static double sphereNaive(double cx, double cy, double cz, double radius,
                              double ox, double oy, double oz, double dx, double dy, double dz) {
        double sx = cx - ox, sy = cy - oy, sz = cz - oz;
        double ds = dx * sx + dy * sy + dz * sz;
        double dd = dx * dx + dy * dy + dz * dz;
        double discriminant = ds * ds - dd * (sx * sx + sy * sy + sz * sz - radius * radius);
        if (discriminant < 0) {
            return Intersect.MISS;
        }
        double root = Math.sqrt(discriminant);
        double t0 = (ds - root) / dd;
        double t1 = (ds + root) / dd;
        if (t0 > 0) {
            return t0;
        }
        return t1 > 0 ? t1 : Intersect.MISS;
    }
}
