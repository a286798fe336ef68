package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import glint.image.FrameBuffer;
import org.junit.jupiter.api.Test;

/**
 * LDR-FLIP against NVIDIA's own evaluator: the expected values are what flip-evaluator 1.7 (its
 * Python package, LDR mode, 67 pixels a degree) gives for the same sRGB images, made here from the
 * formulas below; Glint's float64 agrees with its float32 to about 1e-5.
 */
class FlipTest {

    private static final int W = 48, H = 40;
    private static final double TOLERANCE = 1e-4;

    /** Red rising to the right, green downwards, blue 0.5 (sRGB values). */
    private static double[] ramp() {
        double[] srgb = new double[3 * W * H];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int i = 3 * (y * W + x);
                srgb[i] = x / (W - 1.0);
                srgb[i + 1] = y / (H - 1.0);
                srgb[i + 2] = 0.5;
            }
        }
        return srgb;
    }

    private static double[] uniform(double r, double g, double b) {
        double[] srgb = new double[3 * W * H];
        for (int i = 0; i < srgb.length; i += 3) {
            srgb[i] = r;
            srgb[i + 1] = g;
            srgb[i + 2] = b;
        }
        return srgb;
    }

    private static double mean(double[] map) {
        double s = 0;
        for (double v : map) {
            s += v;
        }
        return s / map.length;
    }

    @Test
    void aWhiteSquareOnARampScoresAsNvidiasEvaluatorDoes() {
        double[] reference = ramp(), test = ramp();
        for (int y = 16; y < 24; y++) {
            for (int x = 20; x < 28; x++) {
                for (int c = 0; c < 3; c++) {
                    test[3 * (y * W + x) + c] = 1;
                }
            }
        }
        double[] map = Flip.errorMap(reference, test, W, H);
        assertEquals(0.0622750, mean(map), TOLERANCE);
        assertEquals(0.9694706, map[18 * W + 22], TOLERANCE);
        assertEquals(0, map[0], TOLERANCE); // far from the square, the images agree
        assertEquals(0, map[35 * W + 10], TOLERANCE);
    }

    @Test
    void uniformImagesScoreTheColourErrorAlone() {
        assertEquals(0.1764808, mean(Flip.errorMap(uniform(0.5, 0.5, 0.5), uniform(0.55, 0.55, 0.55), W, H)), TOLERANCE);
        assertEquals(0.9674007, mean(Flip.errorMap(uniform(0, 0, 0), uniform(1, 1, 1), W, H)), TOLERANCE);
        // green against blue is the largest colour difference FLIP knows: 1 by its definition
        assertEquals(1, mean(Flip.errorMap(uniform(0, 1, 0), uniform(0, 0, 1), W, H)), 1e-9);
    }

    @Test
    void anImageAgainstItselfScoresZeroAndSizesMustMatch() {
        FrameBuffer frame = new FrameBuffer(W, H);
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                frame.set(x, y, x / (double) W, 0.3, y / (double) H);
            }
        }
        assertEquals(0, Flip.of(frame, frame));
        assertEquals("image sizes differ: 48x40 vs 40x48",
                assertThrows(IllegalArgumentException.class, () -> Flip.of(frame, new FrameBuffer(H, W))).getMessage());
    }
}
