package glint.ui.frames;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import glint.image.FrameBuffer;
import glint.image.ImageWriter;
import glint.image.Srgb;
import java.awt.image.BufferedImage;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The window's fast sRGB encoding gives exactly the codes of the PNG writer, rounded and dithered. */
class SrgbEncoderTest {

    @Test
    void equalsSrgbTo8BitAroundEveryCodeBoundary() {
        for (int k = 1; k <= 255; k++) {
            // find the boundary of code k by bisection on float bits, then check it and its neighbours
            int lo = 0;
            int hi = Float.floatToIntBits(1f);
            while (hi - lo > 1) {
                int mid = (lo + hi) >>> 1;
                if (Srgb.to8Bit(Float.intBitsToFloat(mid)) >= k) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            for (int bits = hi - 3; bits <= hi + 3; bits++) {
                float v = Float.intBitsToFloat(bits);
                assertEquals(Srgb.to8Bit(v), SrgbEncoder.code(v), "at " + v);
            }
        }
    }

    @Test
    void equalsSrgbTo8BitOnRandomAndSpecialValues() {
        SplittableRandom random = new SplittableRandom(7);
        for (int i = 0; i < 2_000_000; i++) {
            float v = (float) (i % 2 == 0 ? random.nextDouble() : random.nextDouble() * random.nextDouble() * 0.01);
            assertEquals(Srgb.to8Bit(v), SrgbEncoder.code(v), "at " + v);
        }
        float[] special = {0f, -0f, -1f, 1f, 2f, Float.NaN, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY,
            Float.MIN_VALUE, Math.nextDown(1f), 0.0031308f};
        for (float v : special) {
            assertEquals(Srgb.to8Bit(v), SrgbEncoder.code(v), "at " + v);
        }
    }

    @Test
    void ditheredEqualsSrgbTo8BitAroundEveryCodeBoundaryAtEveryLevel() {
        for (int level = 0; level < glint.image.Dither.LEVELS; level++) {
            for (int k = 1; k <= 255; k++) {
                int lo = 0;
                int hi = Float.floatToIntBits(1f);
                while (hi - lo > 1) {
                    int mid = (lo + hi) >>> 1;
                    if (Srgb.to8Bit(Float.intBitsToFloat(mid), level) >= k) {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                for (int bits = hi - 2; bits <= hi + 2; bits++) {
                    float v = Float.intBitsToFloat(bits);
                    assertEquals(Srgb.to8Bit(v, level), SrgbEncoder.code(v, level), "at " + v + ", level " + level);
                }
            }
        }
    }

    @Test
    void ditheredEqualsSrgbTo8BitOnRandomAndSpecialValues() {
        SplittableRandom random = new SplittableRandom(11);
        for (int i = 0; i < 2_000_000; i++) {
            float v = (float) (i % 2 == 0 ? random.nextDouble() : random.nextDouble() * random.nextDouble() * 0.01);
            int level = random.nextInt(glint.image.Dither.LEVELS);
            assertEquals(Srgb.to8Bit(v, level), SrgbEncoder.code(v, level), "at " + v + ", level " + level);
        }
        float[] special = {0f, -0f, -1f, 1f, 2f, Float.NaN, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY,
            Float.MIN_VALUE, Math.nextDown(1f), 0.0031308f};
        for (float v : special) {
            for (int level = 0; level < glint.image.Dither.LEVELS; level++) {
                assertEquals(Srgb.to8Bit(v, level), SrgbEncoder.code(v, level), "at " + v + ", level " + level);
            }
        }
    }

    @Test
    void imageEqualsTheImageWritersImage() {
        FrameBuffer frame = new FrameBuffer(37, 23);
        SplittableRandom random = new SplittableRandom(3);
        float[] rgb = frame.rgb();
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] = (float) (random.nextDouble() * 1.2 - 0.1);
        }
        BufferedImage expected = ImageWriter.toImage(frame);
        BufferedImage actual = SrgbEncoder.toImage(frame);
        assertArrayEquals(expected.getRGB(0, 0, 37, 23, null, 0, 37), actual.getRGB(0, 0, 37, 23, null, 0, 37));
    }
}
