package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.shading.Optics;
import org.junit.jupiter.api.Test;

/** Schlick against the exact Fresnel equations for ior 1.5, outside and inside the glass. */
class FresnelStabilityTest {

    @Test
    void schlickIsExactAtNormalAndGrazingIncidenceFromOutside() {
        assertEquals(0.04, FresnelCurves.f0(), 1e-15);
        assertEquals(FresnelCurves.exactOutside(0), FresnelCurves.schlickOutside(0), 1e-15);
        assertEquals(1, FresnelCurves.schlickOutside(90), 1e-15);
        assertEquals(1, FresnelCurves.exactOutside(90), 1e-15);
    }

    @Test
    void schlickStaysWithinAFewPercentFromOutside() {
        for (double a : FresnelCurves.angles(0.1)) {
            assertEquals(FresnelCurves.exactOutside(a), FresnelCurves.schlickOutside(a), 0.05, "at " + a);
        }
    }

    @Test
    void insideBelowTheCriticalAngleBothObeyReciprocity() {
        // F(inside, theta_i) = F(outside, theta_t) with sin(theta_t) = 1.5 sin(theta_i), for the exact
        // equations; Glint's Schlick evaluates at the air-side cosine, so it inherits the same identity
        for (double a = 0; a < FresnelCurves.criticalAngleDegrees() - 0.01; a += 0.5) {
            double outside = Math.toDegrees(Math.asin(1.5 * Math.sin(Math.toRadians(a))));
            assertEquals(FresnelCurves.exactOutside(outside), FresnelCurves.exactInside(a), 1e-9, "exact at " + a);
            assertEquals(FresnelCurves.schlickOutside(outside), FresnelCurves.schlickInside(a), 1e-9, "Schlick at " + a);
        }
    }

    @Test
    void pastTheCriticalAngleOnlyTheWrongCosineMissesTotalInternalReflection() {
        double critical = FresnelCurves.criticalAngleDegrees();
        assertEquals(41.81, critical, 0.005);
        for (double a = critical + 0.01; a <= 90; a += 0.5) {
            assertEquals(1, FresnelCurves.exactInside(a), "exact, total internal reflection at " + a);
            assertEquals(1, FresnelCurves.schlickInside(a), "Glint's Schlick at " + a);
        }
        // the slip: F0 + (1 - F0)(1 - cos 45 deg)^5 = 0.04 + 0.96 x 0.00216 = 0.042, where the truth is 1
        assertEquals(0.04 + 0.96 * Math.pow(1 - Math.cos(Math.toRadians(45)), 5),
                FresnelCurves.schlickWrongCosineInside(45), 1e-12);
        assertTrue(FresnelCurves.schlickWrongCosineInside(45) < 0.05);
    }

    @Test
    void reflectanceStaysInTheUnitInterval() {
        for (double a : FresnelCurves.angles(0.05)) {
            for (double f : new double[] {FresnelCurves.exactOutside(a), FresnelCurves.schlickOutside(a),
                    FresnelCurves.exactInside(a), FresnelCurves.schlickInside(a), Optics.schlick(0.04, Math.cos(a))}) {
                assertTrue(f >= 0 && f <= 1, "reflectance " + f + " at " + a);
            }
        }
    }
}
