package glint.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;

import glint.render.FrameBuffer;
import org.junit.jupiter.api.Test;

class PairedFramesTest {

    @Test
    void quantilesInterpolateBetweenRanks() {
        double[] values = {4, 1, 3, 2};
        assertEquals(1, PairedFrames.quantile(values, 0));
        assertEquals(4, PairedFrames.quantile(values, 1));
        assertEquals(2.5, PairedFrames.quantile(values, 0.5));
        assertEquals(1.75, PairedFrames.quantile(values, 0.25));
        assertEquals(3, PairedFrames.quantile(new double[] {3}, 0.75));
    }

    @Test
    void theSummaryGivesEachTracersMedianAndThePairsRatios() {
        // pairs: 10 and 20 ms (2x), 20 and 30 ms (1.5x), 40 and 120 ms (3x)
        long[] glint = {10_000_000, 20_000_000, 40_000_000};
        long[] plain = {20_000_000, 30_000_000, 120_000_000};
        assertEquals("paired: pairs=3 glint_median_ms=20.00 plain_median_ms=30.00 ratio_median=2.000 ratio_q1=1.750"
                + " ratio_q3=2.500", PairedFrames.summary(glint, plain));
    }

    @Test
    void pixelsDifferBeyondTheToleranceOrWhereEitherIsNotANumber() {
        FrameBuffer a = new FrameBuffer(4, 1), b = new FrameBuffer(4, 1);
        a.set(0, 0, 0.5, 0.5, 0.5);
        b.set(0, 0, 0.5, 0.5, 0.5 + 0.5 * PairedFrames.TOLERANCE); // within
        a.set(1, 0, 0.1, 0.2, 0.3);
        b.set(1, 0, 0.1, 0.2 + 2 * PairedFrames.TOLERANCE, 0.3); // beyond, in one channel
        a.set(2, 0, 1000, 0, 0);
        b.set(2, 0, 1000.05, 0, 0); // 5e-5 relative: within
        b.set(3, 0, Double.NaN, 0, 0);
        assertEquals(2, PairedFrames.differingPixels(a, b));
        assertEquals(0, PairedFrames.differingPixels(a, a));
    }
}
