package glint.study;

import java.math.BigDecimal;
import java.math.MathContext;

/**
 * The exact answer to a ray-sphere query whose inputs are the given doubles (floats widen to
 * doubles exactly): the hit/miss decision in exact decimal arithmetic, the nearer positive t to
 * 34 significant digits. The ground truth that {@link SphereStudy} judges each method against.
 */
public final class ExactSphere {

    private static final MathContext DIGITS = MathContext.DECIMAL128;

    private ExactSphere() {
    }

    /**
     * The nearest t > 0 at which o + t d meets the sphere, rounded to double, or
     * {@link Double#POSITIVE_INFINITY} for a miss. Only for a ray origin outside the sphere.
     */
    public static double nearestT(double cx, double cy, double cz, double radius,
                                  double ox, double oy, double oz, double dx, double dy, double dz) {
        BigDecimal fx = exact(ox).subtract(exact(cx));
        BigDecimal fy = exact(oy).subtract(exact(cy));
        BigDecimal fz = exact(oz).subtract(exact(cz));
        BigDecimal ex = exact(dx), ey = exact(dy), ez = exact(dz);
        BigDecimal a = ex.multiply(ex).add(ey.multiply(ey)).add(ez.multiply(ez));
        BigDecimal b = fx.multiply(ex).add(fy.multiply(ey)).add(fz.multiply(ez)).negate();
        BigDecimal c = fx.multiply(fx).add(fy.multiply(fy)).add(fz.multiply(fz)).subtract(exact(radius).pow(2));
        if (c.signum() <= 0) {
            throw new IllegalArgumentException("ray origin inside the sphere");
        }
        // quarter discriminant of a t^2 - 2 b t + c = 0, exact
        BigDecimal disc = b.multiply(b).subtract(a.multiply(c));
        if (disc.signum() < 0 || b.signum() <= 0) {
            return Double.POSITIVE_INFINITY; // line misses, or the sphere lies behind the origin
        }
        // both roots positive; the nearer one in cancellation-free form c / (b + sqrt(disc))
        BigDecimal root = disc.sqrt(DIGITS);
        return c.divide(b.add(root), DIGITS).doubleValue();
    }

    private static BigDecimal exact(double v) {
        return new BigDecimal(v);
    }
}
