package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** SSIM (Wang et al. 2004) against its defining properties. */
class SsimTest {

    private static final int W = 48, H = 40;

    private static double[] noise(long seed, double mean, double spread) {
        Random random = new Random(seed);
        double[] x = new double[W * H];
        for (int i = 0; i < x.length; i++) {
            x[i] = mean + spread * (random.nextDouble() - 0.5);
        }
        return x;
    }

    @Test
    void identicalImagesScoreExactlyOne() {
        double[] x = noise(1, 0.5, 0.6);
        assertEquals(1, Ssim.of(x, x.clone(), W, H), 1e-12);
    }

    @Test
    void constantImagesScoreTheLuminanceTermAlone() {
        // no variance: the contrast-structure term is (0 + C2) / (0 + C2) = 1, SSIM = (2ab + C1) / (a^2 + b^2 + C1)
        double a = 0.3, b = 0.5;
        double[] x = new double[W * H], y = new double[W * H];
        java.util.Arrays.fill(x, a);
        java.util.Arrays.fill(y, b);
        double expected = (2 * a * b + Ssim.C1) / (a * a + b * b + Ssim.C1);
        assertEquals(expected, Ssim.of(x, y, W, H), 1e-12);
    }

    @Test
    void aMeanShiftCostsLessThanNoiseOfTheSameMse() {
        // Wang et al.'s point: equal MSE, very different structure
        double[] x = noise(2, 0.5, 0.2);
        double shift = 0.05;
        double[] shifted = new double[x.length], noisy = new double[x.length];
        Random random = new Random(3);
        for (int i = 0; i < x.length; i++) {
            shifted[i] = x[i] + shift;
            noisy[i] = x[i] + (random.nextBoolean() ? shift : -shift); // same squared error per pixel
        }
        double ssimShift = Ssim.of(x, shifted, W, H), ssimNoise = Ssim.of(x, noisy, W, H);
        assertTrue(ssimShift > 0.98, "a shift of 0.05 on a mean of 0.5 keeps SSIM high: " + ssimShift);
        assertTrue(ssimNoise < 0.9 * ssimShift, "noise of the same MSE scores lower: " + ssimNoise);
    }

    @Test
    void symmetricAndBelowOneForDifferentImages() {
        double[] x = noise(4, 0.4, 0.4), y = noise(5, 0.4, 0.4);
        double xy = Ssim.of(x, y, W, H);
        assertEquals(xy, Ssim.of(y, x, W, H), 1e-15);
        assertTrue(xy < 0.2, "independent noise images are structurally unrelated: " + xy);
    }

    @Test
    void invertedContrastScoresNegative() {
        // y = 2 mean - x: the same mean and variance, covariance -variance: the structure term is about -1
        double[] x = noise(6, 0.5, 0.8), y = new double[x.length];
        for (int i = 0; i < x.length; i++) {
            y[i] = 1.0 - x[i];
        }
        assertTrue(Ssim.of(x, y, W, H) < -0.9);
    }

    @Test
    void frameBuffersAreComparedOnTheirSrgbLuma() {
        FrameBuffer a = new FrameBuffer(16, 16), b = new FrameBuffer(16, 16);
        for (int y = 0; y < 16; y++) {
            for (int x = 0; x < 16; x++) {
                a.set(x, y, 0.2, 0.2, 0.2);
                b.set(x, y, 0.2, 0.2, 0.2);
            }
        }
        assertEquals(1, Ssim.of(a, b), 1e-12);
        b.set(3, 3, 5, 5, 5); // clamped to 1 before encoding, as a viewer sees it
        double[] luma = Ssim.luma(b);
        assertEquals(1, luma[3 * 16 + 3], 1e-12);
        assertEquals(glint.image.Srgb.encode(0.2f), luma[0], 1e-12); // the frame stores float
    }

    @Test
    void imagesSmallerThanTheWindowAreRejected() {
        assertThrows(IllegalArgumentException.class, () -> Ssim.of(new double[100], new double[100], 10, 10));
    }
}
