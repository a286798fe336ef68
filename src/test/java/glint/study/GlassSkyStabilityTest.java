package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Shading;
import glint.render.Tracer;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * A bright sky through a clear glass ball (stability.md, section 6): each Fresnel choice weighs 1,
 * so a sample is the sky or nothing, and the only light lost is that of paths still inside the
 * ball at their last hit, as the closed form says.
 */
class GlassSkyStabilityTest {

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
    void inAFurnaceEverySampleIsTheSkyOrZeroAndTheZerosAreThePathsStillInside() {
        for (int hits : new int[] {3, 5}) {
            PassSamples s = GlassSky.render(false, 64, hits, tracer);
            double[] expected = GlassSky.furnaceExpected(hits, 4);
            long zeros = 0;
            double expectedZeros = 0;
            for (int p = 0; p < expected.length; p++) {
                for (float v : s.values[p]) {
                    assertTrue(v == 0 || v == (float) GlassSky.SKY, "sample " + v + " at pixel " + p);
                    zeros += v == 0 ? 1 : 0;
                }
                expectedZeros += (1 - expected[p]) * 64;
            }
            // zeros are a sum of independent rare events: a standard deviation of about sqrt(expected)
            assertEquals(expectedZeros, zeros, 4 * Math.sqrt(expectedZeros) + 2, hits + " hits");
        }
    }

    @Test
    void overABlackFloorThePathsMeanIsWhittedsSplitOfBothLobesAndNoSampleOutshinesTheSky() {
        int hits = 16, samples = 64;
        PassSamples path = GlassSky.render(true, samples, hits, tracer);
        // Whitted traces both lobes at every glass hit: with no light and no ambient, its pixel is the
        // expected value of the path's choices, for the same sample positions
        RenderScene whitted = RenderScene.compile(GlassSky.scene(true), new RenderSettings(Shading.COOK_TORRANCE, hits, 0,
                1e-9));
        FrameBuffer frame = new FrameBuffer(GlassSky.WIDTH, GlassSky.HEIGHT);
        tracer.render(whitted, frame, samples, 0, 4);
        double sum = 0;
        for (int p = 0; p < GlassSky.WIDTH * GlassSky.HEIGHT; p++) {
            sum += frame.rgb()[3 * p];
        }
        double whittedMean = sum / (GlassSky.WIDTH * GlassSky.HEIGHT);
        assertTrue(Math.abs(path.mean() - whittedMean) <= 4 * path.standardError(),
                "path " + path.mean() + " ± " + path.standardError() + ", Whitted " + whittedMean);
        assertTrue(path.max() <= GlassSky.SKY, "largest sample " + path.max());
        // the upper half of the ball refracts the floor: a sample there brings the sky only when it
        // reflects, about F = 4 % of the time, so one sample's spread is about sqrt(0.96 / 0.04) = 4.9 its mean
        int centre = GlassSky.HEIGHT / 4 * GlassSky.WIDTH + GlassSky.WIDTH / 2;
        double mean = 0, squares = 0;
        for (float v : path.values[centre]) {
            mean += v;
            squares += (double) v * v;
        }
        mean /= samples;
        double spread = Math.sqrt(squares / samples - mean * mean) / mean;
        assertTrue(spread > 3, "one sample's spread " + spread + " of the mean");
    }
}
