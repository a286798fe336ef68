package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The cone of a small sphere light (stability.md, section 7): Glint's 1 - cos theta_max keeps its
 * digits for any r / d, the textbook's cancels.
 */
class ConeStabilityTest {

    /**
     * The roundings between the inputs and the irradiance a sample stands for, each at most u relative:
     * d^2 (three squares, two sums of positive terms: 3 u), r^2 and the quotient sin^2 (2 u), the
     * denominator 1 + sqrt(1 - sin^2) (1.5 u), the quotient (u), 2 pi (0.4 u) and the product (u).
     */
    static final double BOUND = 9 * ConeWidth.U;

    @Test
    void glintsConeAndTheIrradianceItsSampleStandsForKeepTheirDigitsDownToATrillionth() {
        for (double ratio : ConeWidth.ratios()) {
            ConeWidth.Row row = ConeWidth.at(ratio);
            assertTrue(row.glintError() <= BOUND, "r/d " + ratio + ": " + row.glintError() / ConeWidth.U + " u");
            // and the sample stands for c I / d^2 as r goes to 0: 2 / (1 + cos theta_max) exactly
            assertEquals(row.exactIrradiance(), row.glintIrradiance(), BOUND * row.exactIrradiance());
        }
    }

    @Test
    void theTextbooksConeIsRoundingBelowAMillionthAndZeroBelowTenToTheMinusNine() {
        // 1 - sqrt(1 - s) near 1: the rounding of the square root, about u, over a width of about r^2 / (2 d^2)
        boolean fails = false;
        for (double ratio : ConeWidth.ratios()) {
            ConeWidth.Row row = ConeWidth.at(ratio);
            assertTrue(row.textbookError() <= 4 * ConeWidth.U / (ratio * ratio), "r/d " + ratio);
            fails |= ratio < 1e-6 && row.textbookError() > 1e-3;
            if (ratio < 5e-9) { // r^2 / d^2 below u: 1 - r^2/d^2 rounds to 1
                assertEquals(0, row.textbookIrradiance(), "r/d " + ratio);
            }
        }
        assertTrue(fails, "the textbook's error passes 1e-3 somewhere below r/d = 1e-6");
        // where it is not 0 it can be off by a factor: at r/d = 1e-8 it is 2.2 times the light
        assertTrue(ConeWidth.at(1e-8).textbookIrradiance() > 1.5);
    }
}
