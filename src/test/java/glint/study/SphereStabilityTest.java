package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * Ray-sphere tests where the textbook quadratic fails. The bounds follow from the rounding error:
 * with unit round-off u (2^-24 in float, 2^-53 in double) and a sphere of radius r at distance D,
 * the naive discriminant (d.s)^2 - (s.s - r^2) loses about D^2 u against r^2, so it breaks once
 * D ~ r / sqrt(u) (4096 radii in float, ~1e8 in double); the stable form's r^2 - |f - (f.d) d|^2 loses
 * only about D r u, so it breaks at D ~ r / u (~1.7e7 radii in float, ~1e16 in double).
 */
class SphereStabilityTest {

    private static final int N = 24;

    private static SphereErrors far(double distance, SphereMethod method) {
        return SphereStudy.run(SphereView.farSphere(distance, N), method).get(method);
    }

    @Test
    void exactClassificationAgreesWithGeometry() {
        // head-on at distance 10: t = 9; a ray missing by 1e-9 of angle beyond the limb misses
        assertEquals(9, ExactSphere.nearestT(0, 0, 10, 1, 0, 0, 0, 0, 0, 1), 1e-15);
        double limb = Math.asin(0.1);
        double in = limb - 1e-9, out = limb + 1e-9;
        assertTrue(ExactSphere.nearestT(0, 0, 10, 1, 0, 0, 0, Math.sin(in), 0, Math.cos(in)) < 10);
        assertEquals(Double.POSITIVE_INFINITY, ExactSphere.nearestT(0, 0, 10, 1, 0, 0, 0, Math.sin(out), 0, Math.cos(out)));
        assertEquals(Double.POSITIVE_INFINITY, ExactSphere.nearestT(0, 0, -10, 1, 0, 0, 0, 0, 0, 1), "behind");
    }

    @Test
    void glintsStableDoubleFormHasNoWrongPixelUpToAHundredMillionRadii() {
        // error ~ D r u = 1e8 x 1.1e-16 ~ 1e-8 r, far below the 1e-3 tolerance
        for (double distance : new double[] {2, 1e2, 1e4, 1e6, 1e8}) {
            assertEquals(0, far(distance, SphereMethod.STABLE_DOUBLE).wrong(), "at " + distance + " radii");
        }
        Map<SphereMethod, SphereErrors> huge = SphereStudy.run(SphereView.hugeSphere(1e8, N), SphereMethod.STABLE_DOUBLE);
        assertEquals(0, huge.get(SphereMethod.STABLE_DOUBLE).wrong(), "a sphere of radius 1e8 one unit below");
    }

    @Test
    void naiveFloatFormLosesTheSilhouetteBeyondAboutFourThousandRadii() {
        // at 10 radii: D^2 u = 6e-6 r^2, harmless
        assertEquals(0, far(10, SphereMethod.NAIVE_FLOAT).wrong());
        // at 1e4 radii: D^2 u = 6 r^2 > r^2: the discriminant is noise, hits and misses are wrong
        SphereErrors at1e4 = far(1e4, SphereMethod.NAIVE_FLOAT);
        assertTrue(at1e4.hitMissFraction() > 0.1, "wrong hit/miss at 1e4 radii: " + at1e4);
    }

    @Test
    void naiveDoubleFormHoldsTo1e6AndBreaksNear1e8() {
        // D^2 u: 1e12 x 1.1e-16 = 1e-4 r^2 at 1e6 (t off by ~1e-4 r, within tolerance); 1.1 r^2 at 1e8
        assertEquals(0, far(1e6, SphereMethod.NAIVE_DOUBLE).wrong());
        assertTrue(far(1e8, SphereMethod.NAIVE_DOUBLE).hitMissFraction() > 0.1);
    }

    @Test
    void stableFloatFormHoldsWhereTheNaiveOneFailsButNotForever() {
        // D r u = 1e3 x 6e-8 = 6e-5 r at 1e3 radii: exact enough; 6 r at 1e8: the silhouette is gone
        assertEquals(0, far(1e3, SphereMethod.STABLE_FLOAT).wrong());
        assertTrue(far(1e3, SphereMethod.NAIVE_FLOAT).wrong() > 0, "the naive float form already errs at 1e3");
        assertTrue(far(1e8, SphereMethod.STABLE_FLOAT).wrong() > 0);
    }

    @Test
    void aHugeSphereCloseByDefeatsBothFloatFormsButNeitherDoubleOne() {
        // c = |f|^2 - R^2 cancels in both forms: t is off by ~R u relative; 1e6 x 6e-8 = 6 % in float
        Map<SphereMethod, SphereErrors> at1e6 = SphereStudy.run(SphereView.hugeSphere(1e6, N));
        assertTrue(at1e6.get(SphereMethod.NAIVE_FLOAT).wrongFraction() > 0.3);
        assertTrue(at1e6.get(SphereMethod.STABLE_FLOAT).wrongFraction() > 0.3);
        assertEquals(0, at1e6.get(SphereMethod.NAIVE_DOUBLE).wrong());
        assertEquals(0, at1e6.get(SphereMethod.STABLE_DOUBLE).wrong());
        // at R = 1e3 float still gives t to ~6e-5: no wrong pixel
        Map<SphereMethod, SphereErrors> at1e3 = SphereStudy.run(SphereView.hugeSphere(1e3, N));
        assertEquals(0, at1e3.get(SphereMethod.NAIVE_FLOAT).wrong());
        assertEquals(0, at1e3.get(SphereMethod.STABLE_FLOAT).wrong());
    }
}
