package glint.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import glint.render.RenderSettings.Pruning;
import glint.scene.Scene;
import org.junit.jupiter.api.Test;

/**
 * Pruning by Russian roulette: a ray whose path weight falls below min_weight goes on with a
 * probability and a weight that keep the expected value, so a still image converges to the unpruned
 * one; the plain cut-off, kept for comparison, loses that light.
 */
class PruningTest {

    /**
     * One glass sphere (tint c = [0.5, 0.8, 1], ior 1.5) in front of a white background, no lights:
     * the centre ray meets it head-on. R = ((1.5 - 1) / (1.5 + 1))^2 = 0.04 at every surface, T = 0.96.
     */
    private static final String TINTED_GLASS = """
            camera: {position: [0, 0, -5], look_at: [0, 0, 0], fov: 30}
            background: [1, 1, 1]
            ambient: [0, 0, 0]
            objects:
              - {type: sphere, center: [0, 0, 0], radius: 1, material: {type: glass, color: [0.5, 0.8, 1], ior: 1.5}}
            """;
    private static final double[] TINT = {0.5, 0.8, 1};
    private static final double R = 0.04, T = 0.96;

    /**
     * The centre pixel at depth d: the front reflection R, plus the light that enters (T c) and
     * leaves through the back (T c) after 0, 2, 4, ... internal reflections, each pair costing two
     * hits: R + T^2 c^2 (1 + R^2 + R^4 + ...), the sum over the k = 0 .. d - 3 internal reflections the
     * depth leaves room for, every one of them R (normal incidence both ways).
     */
    private static double centre(int depth, double c) {
        if (depth < 2) {
            return 0;
        }
        double inside = 0, reflections = 1;
        for (int k = 0; k <= depth - 3; k++) {
            inside += reflections;
            reflections *= R;
        }
        return R + T * T * c * c * inside;
    }

    private static FrameBuffer centrePixel(Scene scene, int depth, double minWeight, Pruning pruning, int frameIndex,
                                           Tracer tracer) {
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, depth, minWeight, Renders.EPSILON)
                .withPruning(pruning);
        FrameBuffer frame = new FrameBuffer(1, 1);
        tracer.render(RenderScene.compile(scene, settings), frame, 1, frameIndex, 1);
        return frame;
    }

    @Test
    void workedExampleEachDepthAddsTheInternalReflectionsItMakesRoomFor() {
        Scene scene = Renders.scene(TINTED_GLASS);
        try (Tracer tracer = new Tracer(1)) {
            for (int depth = 2; depth <= 8; depth++) {
                FrameBuffer frame = centrePixel(scene, depth, 0, Pruning.ROULETTE, 0, tracer);
                for (int ch = 0; ch < 3; ch++) {
                    assertEquals(centre(depth, TINT[ch]), frame.get(0, 0, ch), 1e-6, "depth " + depth + ", channel " + ch);
                }
            }
        }
        // the values by hand: depth 5 adds 0.9216 x 0.0016 x c^2 over depth 4 (two internal reflections)
        assertEquals(0.04, centre(2, 1), 1e-15);
        assertEquals(0.04 + 0.9216, centre(3, 1), 1e-15);
        assertEquals(0.9216 * 0.0016 * 0.25, centre(5, 0.5) - centre(4, 0.5), 1e-15);
    }

    @Test
    void plainCutOffStopsAtDepthFourRouletteKeepsTheDeeperLightInTheMean() {
        Scene scene = Renders.scene(TINTED_GLASS);
        int frames = 4000;
        double[] sum = new double[3], sumSquares = new double[3];
        try (Tracer tracer = new Tracer(1)) {
            // the twice reflected ray weighs 0.96 x 0.04 x 0.04 = 0.0015 < 0.01: the cut-off drops it at any depth
            FrameBuffer cut = centrePixel(scene, 8, 0.01, Pruning.CUTOFF, 0, tracer);
            for (int ch = 0; ch < 3; ch++) {
                assertEquals(centre(4, TINT[ch]), cut.get(0, 0, ch), 1e-6);
            }
            for (int f = 0; f < frames; f++) {
                FrameBuffer frame = centrePixel(scene, 8, 0.01, Pruning.ROULETTE, f, tracer);
                for (int ch = 0; ch < 3; ch++) {
                    double v = frame.get(0, 0, ch);
                    sum[ch] += v;
                    sumSquares[ch] += v * v;
                }
            }
        }
        for (int ch = 0; ch < 3; ch++) {
            double mean = sum[ch] / frames;
            double variance = (sumSquares[ch] - frames * mean * mean) / (frames - 1);
            double standardError = Math.sqrt(variance / frames);
            double exact = centre(8, TINT[ch]);
            assertTrue(standardError > 0, "the roulette drew both ways");
            assertEquals(exact, mean, 4 * standardError, "channel " + ch);
            // the loss the cut-off keeps is many standard errors: the test can tell the two apart
            assertTrue(exact - centre(4, TINT[ch]) > 10 * standardError, "channel " + ch);
        }
    }

    @Test
    void aRayBelowTheThresholdGoesOnAtTheThresholdWithTheExpectedValueKept() {
        RenderScene scene = RenderScene.compile(Renders.scene(TINTED_GLASS),
                new RenderSettings(Shading.COOK_TORRANCE, 5, 0.05, Renders.EPSILON));
        WhittedIntegrator it = new WhittedIntegrator();
        it.prepare(scene);
        assertEquals(1, it.keep(0.05));
        assertEquals(1, it.keep(0.7));
        assertEquals(0, it.keep(0));
        for (double w : new double[] {0.04, 0.01, 0.001}) {
            int draws = 200_000, survived = 0;
            double sum = 0;
            for (int i = 0; i < draws; i++) {
                it.beginPath(i, 3, i % 16, 16);
                double keep = it.keep(w);
                if (keep > 0) {
                    survived++;
                    // bounded: a survivor carries exactly min_weight, never more than the threshold
                    assertEquals(0.05, w * keep, 1e-15);
                } else {
                    assertEquals(0, keep);
                }
                sum += w * keep;
            }
            double q = w / 0.05;
            double standardError = 0.05 * Math.sqrt(q * (1 - q) / draws);
            assertEquals(w, sum / draws, 4 * standardError, "weight " + w);
            assertEquals(q, (double) survived / draws, 4 * Math.sqrt(q * (1 - q) / draws));
        }
    }

    @Test
    void theCutOffNeverDraws() {
        RenderScene scene = RenderScene.compile(Renders.scene(TINTED_GLASS),
                new RenderSettings(Shading.COOK_TORRANCE, 5, 0.05, Renders.EPSILON).withPruning(Pruning.CUTOFF));
        WhittedIntegrator it = new WhittedIntegrator();
        it.prepare(scene);
        for (int i = 0; i < 1000; i++) {
            it.beginPath(i, 0, 0, 1);
            assertEquals(0, it.keep(0.049));
            assertEquals(1, it.keep(0.05));
        }
    }

    /** Glass and mirrors under a light: every kind of branch, lit and unlit, reflected and refracted. */
    private static final String GLASS_ON_MIRROR = """
            camera: {position: [0, 2, -6], look_at: [0, 0.6, 0], fov: 50}
            background: [0.6, 0.7, 0.9]
            ambient: [0.02, 0.02, 0.02]
            lights:
              - {type: point, position: [-4, 8, -5], intensity: 120}
            materials:
              green: {type: glass, color: [0.6, 0.9, 0.5], ior: 1.5}
              clear: {type: glass, ior: 1.33}
              mirror: {type: metal, color: [0.9, 0.9, 0.9], roughness: 0}
              gold: {type: metal, color: [1.0, 0.77, 0.34], roughness: 0.1}
            objects:
              - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: mirror}
              - {type: sphere, center: [-1.3, 0.6, 0], radius: 0.6, material: green}
              - {type: sphere, center: [0, 0.6, 0.6], radius: 0.6, material: clear}
              - {type: sphere, center: [1.3, 0.6, 0], radius: 0.6, material: gold}
              - {type: sphere, center: [0.4, 0.25, -1.2], radius: 0.25, material: {type: matte, color: [0.8, 0.2, 0.1]}}
            """;

    @Test
    void theMeanOfPrunedFramesIsTheUnprunedImageWithinItsStandardError() {
        for (Shading shading : Shading.values()) {
            Scene scene = Renders.scene(GLASS_ON_MIRROR);
            int w = 32, h = 24, frames = 400, depth = 8;
            double minWeight = 0.2;
            FrameBuffer exact = new FrameBuffer(w, h);
            FrameBuffer frame = new FrameBuffer(w, h);
            double[][] frameMeans = new double[3][frames];
            double cutMean[] = new double[3];
            try (Tracer tracer = new Tracer(2)) {
                tracer.render(RenderScene.compile(scene, new RenderSettings(shading, depth, 0, Renders.EPSILON)),
                        exact, 1, 0, 4);
                RenderScene pruned = RenderScene.compile(scene,
                        new RenderSettings(shading, depth, minWeight, Renders.EPSILON));
                for (int f = 0; f < frames; f++) {
                    tracer.render(pruned, frame, 1, f, 4);
                    for (int ch = 0; ch < 3; ch++) {
                        frameMeans[ch][f] = imageMean(frame, ch);
                    }
                }
                tracer.render(RenderScene.compile(scene, new RenderSettings(shading, depth, minWeight, Renders.EPSILON)
                        .withPruning(Pruning.CUTOFF)), frame, 1, 0, 4);
                for (int ch = 0; ch < 3; ch++) {
                    cutMean[ch] = imageMean(frame, ch);
                }
            }
            for (int ch = 0; ch < 3; ch++) {
                double sum = 0, sumSquares = 0;
                for (double m : frameMeans[ch]) {
                    sum += m;
                    sumSquares += m * m;
                }
                double mean = sum / frames;
                double standardError = Math.sqrt((sumSquares - frames * mean * mean) / (frames - 1) / frames);
                double truth = imageMean(exact, ch);
                String where = shading + ", channel " + ch;
                assertTrue(standardError > 0, where);
                // the expectation is kept: neither light lost nor energy added
                assertEquals(truth, mean, 4 * standardError, where + ": mean " + mean + ", unpruned " + truth);
                // the same threshold as a plain cut-off loses light, by far more than that error
                assertTrue(truth - cutMean[ch] > 8 * standardError, where + ": cut-off " + cutMean[ch]);
            }
        }
    }

    private static double imageMean(FrameBuffer frame, int channel) {
        double sum = 0;
        for (int y = 0; y < frame.height(); y++) {
            for (int x = 0; x < frame.width(); x++) {
                sum += frame.get(x, y, channel);
            }
        }
        return sum / (frame.width() * frame.height());
    }

    @Test
    void withoutPruningTheRouletteDrawsNothingAndChangesNoBit() {
        Scene scene = Renders.scene(GLASS_ON_MIRROR);
        for (Shading shading : Shading.values()) {
            RenderSettings off = new RenderSettings(shading, 7, 0, Renders.EPSILON);
            FrameBuffer roulette = new FrameBuffer(40, 30), cut = new FrameBuffer(40, 30);
            try (Tracer tracer = new Tracer(2)) {
                tracer.render(RenderScene.compile(scene, off), roulette, 4, 0, 3);
                tracer.render(RenderScene.compile(scene, off.withPruning(Pruning.CUTOFF)), cut, 4, 0, 3);
            }
            assertArrayEquals(cut.rgb(), roulette.rgb(), shading.toString());
        }
    }
}
