package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Sampling a white GGX conductor at grazing views and tiny roughness: Glint's visible-normal
 * sampling against the textbook's sampling of all normals (stability.md, section 6).
 */
class GgxSamplingStabilityTest {

    @Test
    void glintsWeightIsFiniteAndAtMostOneAtEveryViewWhileTheTextbooksGrowsAtGrazingViews() {
        for (double roughness : PathStability.GGX_ROUGHNESS) {
            for (double cos : PathStability.VIEW_COSINES) {
                GgxSampling.Stats g = GgxSampling.glint(roughness, cos, 64);
                assertEquals(0, g.nonFinite(), "roughness " + roughness + ", cos " + cos);
                assertTrue(g.maxWeight() <= 1, "weight " + g.maxWeight() + " at roughness " + roughness + ", cos " + cos);
            }
            // all normals, weight G2 (wo.h) / (wo.n h.n): at a grazing view the few normals that face it weigh most
            double textbook = GgxSampling.textbook(roughness, 1e-4, 64).maxWeight();
            assertTrue(textbook > 10, "textbook's largest weight " + textbook + " at roughness " + roughness);
        }
    }

    @Test
    void bothSamplingsEstimateTheSameAlbedoAndGlintsMatchesItsClosedForm() {
        // alpha = 1: D = 1/pi and the albedo straight on is int_0^1 mu / (1 + mu) dmu = 1 - ln 2
        assertEquals(1 - Math.log(2), GgxSampling.glint(1, 1, 128).meanWeight(), 2e-3);
        // views up to 60 degrees: further down, the textbook's heavy tail needs more samples than the grid has
        for (double roughness : new double[] {0.1, 0.3, 1}) {
            for (double cos : new double[] {1, 0.5}) {
                assertEquals(GgxSampling.textbook(roughness, cos, 128).meanWeight(),
                        GgxSampling.glint(roughness, cos, 128).meanWeight(), 2e-3, "roughness " + roughness + ", cos " + cos);
            }
        }
    }

    @Test
    void visibleNormalsLoseFewSamplesBelowTheHorizonWhereAllNormalsLoseHalf() {
        for (double roughness : new double[] {PathStability.GGX_ROUGHNESS[0], 0.1, 0.3}) {
            for (double cos : PathStability.VIEW_COSINES) {
                double lost = GgxSampling.glint(roughness, cos, 64).lostFraction();
                assertTrue(lost < 0.05, lost + " lost at roughness " + roughness + ", cos " + cos);
            }
            assertEquals(0.5, GgxSampling.textbook(roughness, 1e-6, 64).lostFraction(), 0.01);
        }
    }
}
