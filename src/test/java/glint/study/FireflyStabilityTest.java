package glint.study;

import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.render.Tracer;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Fireflies from a glossy bounce to a point light (stability.md, section 6): the path integrator's
 * mean stays right while its spread grows as the metal wall's roughness falls, and below the delta
 * mirror's threshold the reflected light is gone.
 */
class FireflyStabilityTest {

    private static Tracer tracer;

    @BeforeAll
    static void start() {
        tracer = new Tracer(2);
    }

    @AfterAll
    static void stop() {
        tracer.close();
    }

    @Test
    void aRoughWallsReflectedLightMatchesTheMirrorImageWithinThreeStandardErrors() {
        double mirror = Fireflies.imageMean(true, 4);
        for (double roughness : new double[] {0.15, 0.2}) {
            PassSamples s = Fireflies.render(roughness, 256, tracer);
            double error = s.mean() - mirror;
            assertTrue(Math.abs(error) <= 3 * s.standardError(), "roughness " + roughness + ": mean " + s.mean()
                    + ", mirror image " + mirror + ", standard error " + s.standardError());
            // and the reflected light is there: the direct light alone is 20 % less
            assertTrue(s.mean() > 1.1 * Fireflies.imageMean(false, 4));
        }
    }

    @Test
    void belowTheMirrorThresholdTheWallIsADeltaMirrorAndTheFloorHasOnlyItsDirectLight() {
        double direct = Fireflies.imageMean(false, 4);
        PassSamples s = Fireflies.render(0.0316, 64, tracer); // alpha 9.99e-4 < MIRROR_ALPHA
        assertTrue(Math.abs(s.mean() - direct) <= 3 * s.standardError(), "mean " + s.mean() + ", direct " + direct);
        assertTrue(s.standardError() < 3e-3 * direct, "standard error " + s.standardError());
        assertTrue(s.max() < 5 * s.mean(), "largest sample " + s.max() + ": no fireflies without a lobe");
    }

    @Test
    void theSpreadOfASampleGrowsAsOneOverAlphaAndEverySampleIsFinite() {
        PassSamples narrow = Fireflies.render(0.06, 256, tracer), wide = Fireflies.render(0.2, 256, tracer);
        assertTrue(Double.isFinite(narrow.max()) && Double.isFinite(wide.max()));
        double narrowSpread = narrow.sampleStd() / narrow.mean(), wideSpread = wide.sampleStd() / wide.mean();
        // alpha 0.0036 against 0.04: 11 times narrower; a lobe hit 1/alpha^2 as bright, alpha^2 as likely
        assertTrue(narrowSpread > 4 * wideSpread, "spread " + narrowSpread + " against " + wideSpread);
        assertTrue(narrow.max() / narrow.mean() > 20 * wide.max() / wide.mean());
    }
}
