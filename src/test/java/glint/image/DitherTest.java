package glint.image;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The dither before 8 bits: the same bytes every time, within one code of rounding, and no bands. */
class DitherTest {

    private static final int W = 256;
    private static final int H = 64;

    /** The linear value whose sRGB encoding is {@code code} (in code units, 0 to 255) exactly. */
    private static double linearOfCode(double code) {
        double c = code / 255;
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }

    /** A smooth ramp from left to right across a few codes, as a lit floor is: the banding case. */
    private static FrameBuffer ramp(double fromCode, double toCode) {
        FrameBuffer frame = new FrameBuffer(W, H);
        float[] rgb = frame.rgb();
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                float v = (float) linearOfCode(fromCode + (toCode - fromCode) * (x + 0.5) / W);
                int i = 3 * (y * W + x);
                rgb[i] = v;
                rgb[i + 1] = v * 0.8f;
                rgb[i + 2] = v * 0.6f;
            }
        }
        return frame;
    }

    private static int[] pixels(BufferedImage image) {
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    @Test
    void theSameFrameGivesTheSameBytesEveryTime(@TempDir Path dir) throws IOException {
        FrameBuffer frame = ramp(40, 44);
        Path first = dir.resolve("a.png"), second = dir.resolve("b.png");
        ImageWriter.write(frame, first);
        ImageWriter.write(frame, second);
        assertArrayEquals(Files.readAllBytes(first), Files.readAllBytes(second));
        assertArrayEquals(pixels(ImageWriter.toImage(frame)), pixels(ImageWriter.toImage(ramp(40, 44))));
    }

    @Test
    void theLevelsOfAPixelDependOnItsCoordinatesAlone() {
        int[][] levels = new int[H][W];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                levels[y][x] = Dither.levels(x, y);
            }
        }
        for (int y = H - 1; y >= 0; y--) { // asked again in another order
            for (int x = W - 1; x >= 0; x--) {
                assertEquals(levels[y][x], Dither.levels(x, y));
            }
        }
    }

    @Test
    void everyCodeIsWithinOneOfPlainRoundingAndExactCodesStay() {
        SplittableRandom random = new SplittableRandom(5);
        for (int i = 0; i < 1_000_000; i++) {
            double v = random.nextDouble() * 1.1 - 0.05;
            int level = random.nextInt(Dither.LEVELS);
            int dithered = Srgb.to8Bit(v, level);
            assertTrue(Math.abs(dithered - Srgb.to8Bit(v)) <= 1, () -> v + " at level " + level);
            assertTrue(dithered >= 0 && dithered <= 255);
        }
        for (int code = 0; code <= 255; code++) {
            for (int level = 0; level < Dither.LEVELS; level++) {
                assertEquals(code, Srgb.to8Bit(linearOfCode(code), level), "code " + code + ", level " + level);
            }
        }
    }

    @Test
    void theLevelsAreSpreadEvenly() {
        int[] count = new int[Dither.LEVELS];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int levels = Dither.levels(x, y);
                for (int c = 0; c < 3; c++) {
                    count[Dither.channel(levels, c)]++;
                }
            }
        }
        int expected = 3 * W * H / Dither.LEVELS; // 768
        for (int level = 0; level < Dither.LEVELS; level++) {
            assertTrue(Math.abs(count[level] - expected) < expected / 5, "level " + level + ": " + count[level]);
        }
    }

    /**
     * Each band of 8 columns of the ramp (512 pixels, an eighth of a code wide) averages to its exact value
     * within a tenth of a code, where rounding is off by up to half a code: it steps in bands a quarter of
     * the width apart.
     */
    @Test
    void aRampAveragesToItsExactValueInsteadOfBanding() {
        int[] image = pixels(ImageWriter.toImage(ramp(40, 44)));
        double worstDithered = 0, worstRounded = 0;
        for (int x0 = 0; x0 < W; x0 += 8) {
            double exact = 0, dithered = 0, rounded = 0;
            for (int x = x0; x < x0 + 8; x++) {
                double value = 40 + 4 * (x + 0.5) / W;
                for (int y = 0; y < H; y++) {
                    exact += value;
                    rounded += Math.round(value);
                    dithered += image[y * W + x] >>> 16 & 0xff;
                }
            }
            worstDithered = Math.max(worstDithered, Math.abs(dithered - exact) / (8 * H));
            worstRounded = Math.max(worstRounded, Math.abs(rounded - exact) / (8 * H));
        }
        assertTrue(worstDithered < 0.1, "dithered bands off by up to " + worstDithered);
        assertTrue(worstRounded > 0.4, "rounded bands off by up to " + worstRounded);
    }
}
