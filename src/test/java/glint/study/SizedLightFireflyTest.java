package glint.study;

import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.render.Tracer;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Fireflies from a glossy bounce to a small sphere light (stability.md, section 7): light samples
 * alone, BSDF samples alone and both by the power heuristic (Glint's path integrator, and the
 * study's estimator of it) have the same mean; light samples alone have fireflies as 1/alpha^2,
 * BSDF samples alone as the light's radiance, 1/r^2, and MIS keeps every sample below the light's
 * radiance with the spread of the better of the two.
 */
class SizedLightFireflyTest {

    static final int SAMPLES = 1 << 17, REFERENCE = 1 << 20, PRODUCT = 256;
    private static Tracer tracer;

    @BeforeAll
    static void start() {
        tracer = new Tracer(2);
    }

    @AfterAll
    static void stop() {
        tracer.close();
    }

    private static LightStability.Cell cell(double radius, double roughness) {
        return LightStability.cell(radius, roughness, SAMPLES, REFERENCE, PRODUCT, tracer);
    }

    /** The product, then MIS, light samples only, BSDF samples only. */
    private static SizedLightFireflies.Stats method(LightStability.Cell c, int m) {
        return c.methods()[m];
    }

    @Test
    void everyWayOfFindingTheLightHasTheReferencesMeanWithinThreeStandardErrors() {
        // a light and a lobe where no strategy is hopeless: r = 0.05 and 0.1, roughness 0.2
        for (double radius : new double[] {0.05, 0.1}) {
            LightStability.Cell c = cell(radius, 0.2);
            for (int m = 0; m < 4; m++) {
                SizedLightFireflies.Stats s = method(c, m);
                double error = Math.hypot(s.standardError(), c.reference().standardError());
                assertTrue(Math.abs(s.mean() - c.reference().mean()) <= 3 * error, "r " + radius + ", method " + m
                        + ": " + s.mean() + " against " + c.reference().mean() + " ± " + error);
            }
        }
    }

    @Test
    void misNeverOutshinesTheLightWhileLightSamplesAloneDoAtALowRoughness() {
        // a MIS sample is at most 2 albedo L: the light sample's part f cos L p_l / (p_l^2 + p_b^2) <= L w / 2
        // (w = f cos / p_b <= 1, a BSDF sample's weight), the BSDF sample's part L w, at the floor and the wall
        double radius = 0.1, radiance = Fireflies.INTENSITY / (Math.PI * radius * radius);
        LightStability.Cell c = cell(radius, 0.04);
        for (int m = 0; m < 2; m++) {
            SizedLightFireflies.Stats s = method(c, m);
            assertTrue(s.maxOverMean() * s.mean() <= 2 * Fireflies.ALBEDO * radiance, "method " + m);
        }
        SizedLightFireflies.Stats light = method(c, 2), mis = method(c, 1);
        // light samples alone: f ~ 1 / alpha^2 where the cone meets the narrow lobe, unbounded by the light
        // (2 albedo L, MIS's bound, is L here)
        assertTrue(light.maxOverMean() * light.mean() > 4 * radiance, "largest " + light.maxOverMean() * light.mean());
        assertTrue(light.maxOverMean() > 20 * mis.maxOverMean(), light.maxOverMean() + " against " + mis.maxOverMean());
    }

    @Test
    void bsdfSamplesAloneHaveTheTinyLightsFirefliesThatMisLeavesToTheLightSample() {
        // r = 0.005 from the floor 0.71 away: a cosine sample meets the light with probability about 3.5e-5
        LightStability.Cell c = cell(0.005, 0.2);
        SizedLightFireflies.Stats bsdf = method(c, 3), mis = method(c, 1), product = method(c, 0);
        assertTrue(bsdf.maxOverMean() > 10 * mis.maxOverMean(), bsdf.maxOverMean() + " against " + mis.maxOverMean());
        assertTrue(bsdf.relativeStd() > 5 * mis.relativeStd());
        // the product's path integrator spreads as the study's MIS does, not as BSDF samples alone
        assertTrue(bsdf.relativeStd() > 5 * product.relativeStd());
    }
}
