package glint.image;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The sRGB encoding of IEC 61966-2-1 at known values. */
class SrgbTest {

    @Test
    void endpointsAndClamping() {
        assertEquals(0, Srgb.to8Bit(0));
        assertEquals(255, Srgb.to8Bit(1));
        assertEquals(0, Srgb.to8Bit(-3));
        assertEquals(255, Srgb.to8Bit(7.5));
        assertEquals(0, Srgb.to8Bit(Double.NaN));
    }

    @Test
    void linearSegmentBelowTheBreakPoint() {
        assertEquals(12.92 * 0.002, Srgb.encode(0.002), 1e-15);
    }

    @Test
    void bothSegmentsMeetAtTheBreakPoint() {
        // 12.92 * 0.0031308 = 0.0404499 and 1.055 * 0.0031308^(1/2.4) - 0.055 = 0.0404512
        assertEquals(0.04045, Srgb.encode(0.0031308), 2e-6);
        assertEquals(0.04045, Srgb.encode(0.0031309), 2e-6);
    }

    @Test
    void midGreyAndEighteenPercentGrey() {
        // 1.055 * 0.5^(1/2.4) - 0.055 = 0.735357 -> 187.5 -> 188; 0.18 -> 0.461356 -> 117.6 -> 118
        assertEquals(0.735357, Srgb.encode(0.5), 1e-6);
        assertEquals(188, Srgb.to8Bit(0.5));
        assertEquals(118, Srgb.to8Bit(0.18));
    }
}
