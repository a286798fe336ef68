package glint.study;

import glint.shading.LightSample;
import glint.shading.Lights;
import glint.shading.SphereLightSampler;
import java.math.BigDecimal;
import java.math.MathContext;
import java.util.List;

/**
 * The width of the cone a sphere light of radius r subtends from a point at distance d, 1 - cos
 * theta_max with sin^2 theta_max = r^2 / d^2: the textbook's 1 - sqrt(1 - r^2 / d^2), which cancels
 * when r / d is small, against Glint's, measured through the product's {@link SphereLightSampler}
 * (the irradiance its sample stands for, L 2 pi (1 - cos theta_max)), both against the exact value
 * of the same double inputs in 60-digit decimal arithmetic.
 */
final class ConeWidth {

    static final double U = Math.ulp(1.0) / 2;
    /** The light's radiance, a power of two: multiplying by it is exact. */
    static final double RADIANCE = 4;
    /** The light's centre seen from the origin: an oblique direction, every coordinate non-zero. */
    static final double[] AXIS = {0.48, 0.6, 0.64};

    private static final MathContext MC = new MathContext(60);

    private ConeWidth() {
    }

    /** r / d from 10^-0.25 down to 10^-12, four a decade. */
    static double[] ratios() {
        double[] r = new double[48];
        for (int k = 1; k <= r.length; k++) {
            r[k - 1] = Math.pow(10, -k / 4.0);
        }
        return r;
    }

    /** The relative errors at one r / d, and the irradiance a sample stands for over c I / d^2. */
    record Row(double ratio, double textbookError, double glintError, double textbookIrradiance,
               double glintIrradiance, double exactIrradiance) {
    }

    /**
     * One light of radius {@code ratio} at distance 1 (its centre at {@link #AXIS} rounded), seen from
     * the origin: each form's relative error in 1 - cos theta_max, and the irradiance each makes
     * a sample stand for, over c I / d^2 (1 as r goes to 0; c I = L pi r^2).
     */
    static Row at(double ratio) {
        double lx = AXIS[0], ly = AXIS[1], lz = AXIS[2], radius = ratio;
        BigDecimal d2 = square(lx).add(square(ly), MC).add(square(lz), MC);
        BigDecimal sin2 = square(radius).divide(d2, MC);
        BigDecimal cos = BigDecimal.ONE.subtract(sin2, MC).sqrt(MC);
        BigDecimal exact = sin2.divide(BigDecimal.ONE.add(cos, MC), MC);
        // the textbook, as written
        double distance2 = lx * lx + ly * ly + lz * lz;
        double textbook = 1 - Math.sqrt(1 - radius * radius / distance2);
        // Glint's: the irradiance the product's sample stands for, L 2 pi (1 - cos theta_max)
        Lights lights = Lights.of(List.of(new Lights.Light(new SphereLightSampler(),
                SphereLightSampler.data(lx, ly, lz, radius, RADIANCE, RADIANCE, RADIANCE), null)));
        LightSample sample = new LightSample();
        double glintIrradiance = lights.sample(0, 0, 0, 0, 0.5, 0.5, sample) ? sample.irradianceR : 0;
        BigDecimal twoPiL = new BigDecimal(2 * RADIANCE).multiply(PI, MC);
        BigDecimal exactIrradiance = twoPiL.multiply(exact, MC);
        // c I / d^2 = L pi r^2 / d^2
        BigDecimal pointIrradiance = new BigDecimal(RADIANCE).multiply(PI, MC).multiply(sin2, MC);
        double textbookIrradiance = new BigDecimal(textbook).multiply(twoPiL, MC).divide(pointIrradiance, MC)
                .doubleValue();
        return new Row(ratio, relative(new BigDecimal(textbook), exact),
                relative(new BigDecimal(glintIrradiance), exactIrradiance), textbookIrradiance,
                new BigDecimal(glintIrradiance).divide(pointIrradiance, MC).doubleValue(),
                exactIrradiance.divide(pointIrradiance, MC).doubleValue());
    }

    private static final BigDecimal PI = new BigDecimal(
            "3.14159265358979323846264338327950288419716939937510582097494459230781640628620899863");

    private static BigDecimal square(double v) {
        BigDecimal b = new BigDecimal(v);
        return b.multiply(b, MC);
    }

    private static double relative(BigDecimal value, BigDecimal exact) {
        return value.subtract(exact, MC).abs().divide(exact, MC).doubleValue();
    }
}
