package glint.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Adaptive sampling ({@link Convergence}): the noise estimate from a pixel's round means, the minimum, the
 * neighbourhood, the cap; pixels that stop get no more samples and start no path; the same samples and bytes at
 * any thread count and tile size, with the path and bdpt integrators.
 */
class ConvergenceTest {

    /** The sky above the horizon (no noise at all), a lit floor with a ball below it. */
    private static final String SKY_AND_FLOOR = """
            camera: {position: [0, 1, -4], look_at: [0, 1, 0], fov: 50}
            background: [0.4, 0.5, 0.8]
            lights:
              - {type: point, position: [2, 4, -2], radius: 0.3, intensity: 30}
            objects:
              - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
              - {type: sphere, center: [0, 0.6, 0.5], radius: 0.6, material: {type: metal, roughness: 0.3}}
            """;

    /** Feeds a 1 x 1 refinement rounds whose every pass has the value of that round. */
    private static Convergence fed(double threshold, double... roundValues) {
        Convergence c = new Convergence(1, 1, threshold, 4096);
        FrameBuffer pass = new FrameBuffer(1, 1);
        for (double v : roundValues) {
            pass.set(0, 0, v, v, v); // grey: its luminance is v
            c.add(pass, Convergence.ROUND, 0, 1);
            c.passesAdded(Convergence.ROUND);
        }
        return c;
    }

    @Test
    void theNoiseIsTheStandardErrorOfTheRoundMeansOverTheirMean() {
        // 8 rounds of means 1 and 3: mean 2, sample variance 8/7, standard error sqrt(8/7 / 8)
        Convergence c = fed(0, 1, 3, 1, 3, 1, 3, 1, 3);
        assertEquals(Math.sqrt(1.0 / 7) / 2, c.noise(0), 1e-12);
        assertEquals(c.noise(0), c.relativeNoise(), 1e-12);
        assertEquals(64, c.samples(0));
        assertTrue(Double.isNaN(fed(0, 1).noise(0)), "one round: no spread yet");
        double[] average = new double[3];
        c.average(0, average, 0);
        assertArrayEquals(new double[] {2, 2, 2}, average, 1e-12);
        // a dark pixel is judged against DARKEST: means 0 and 2e-4 have a standard error of 1e-4/sqrt(7)... over 1e-3
        Convergence dark = fed(0, 0, 2e-4, 0, 2e-4, 0, 2e-4, 0, 2e-4);
        assertEquals(Math.sqrt(8.0 / 7 * 1e-8 / 8) / Convergence.DARKEST, dark.noise(0), 1e-6);
    }

    @Test
    void aPixelStopsBelowTheThresholdOnlyAfterTheMinimum() {
        double noise = Math.sqrt(1.0 / 7) / 2; // 0.189 after 8 rounds of 1, 3, ...
        assertFalse(fed(noise * 1.01, 1, 3, 1, 3, 1, 3, 1).done(), "7 rounds: below the minimum of 8");
        assertTrue(fed(noise * 1.01, 1, 3, 1, 3, 1, 3, 1, 3).done(), "8 rounds and below the threshold");
        assertFalse(fed(noise * 0.99, 1, 3, 1, 3, 1, 3, 1, 3).done(), "above it");
        assertFalse(fed(0, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2).done(), "threshold 0: no pixel stops before the cap");
        assertTrue(fed(0.01, 2, 2, 2, 2, 2, 2, 2, 2).done(), "no noise at all: stops at the minimum");
    }

    @Test
    void aPixelStopsOnlyWhenItsWholeNeighbourhoodHasConverged() {
        // 5 x 5: only the centre is noisy; its 8 neighbours go on, the 16 pixels around them stop
        Convergence c = new Convergence(5, 5, 0.05, 4096);
        FrameBuffer pass = new FrameBuffer(5, 5);
        for (int round = 0; round < Convergence.MIN_ROUNDS; round++) {
            for (int y = 0; y < 5; y++) {
                for (int x = 0; x < 5; x++) {
                    double v = x == 2 && y == 2 ? round % 2 * 2 : 1;
                    pass.set(x, y, v, v, v);
                }
            }
            c.add(pass, Convergence.ROUND, 0, 25);
            c.passesAdded(Convergence.ROUND);
        }
        boolean[] active = c.active();
        for (int y = 0; y < 5; y++) {
            for (int x = 0; x < 5; x++) {
                boolean near = Math.abs(x - 2) <= 1 && Math.abs(y - 2) <= 1;
                assertEquals(near, active[y * 5 + x], x + "," + y);
            }
        }
        assertEquals(9, c.activePixels());
        // the pixels that stopped take no more of what a pass holds
        pass.set(0, 0, 100, 100, 100);
        c.add(pass, 1, 0, 25);
        c.passesAdded(1);
        assertEquals(64, c.samples(0));
        assertEquals(65, c.samples(12));
        double[] corner = new double[3];
        c.average(0, corner, 0);
        assertArrayEquals(new double[] {1, 1, 1}, corner, 0);
    }

    @Test
    void theCapStopsEveryPixelAndNoCallCrossesARoundOrTheCap() {
        Convergence c = new Convergence(2, 1, 0.01, 20);
        FrameBuffer pass = new FrameBuffer(2, 1);
        int calls = 0;
        while (!c.done()) {
            int count = c.inOneCall(16);
            assertTrue(c.passes() / Convergence.ROUND == (c.passes() + count - 1) / Convergence.ROUND,
                    "within one round: " + c.passes() + " + " + count);
            pass.set(0, 0, calls % 3, 0, 0);
            pass.set(1, 0, calls % 2, 1, 0);
            c.add(pass, count, 0, 2);
            c.passesAdded(count);
            calls++;
        }
        assertEquals(20, c.passes());
        assertEquals(0, c.activePixels());
        assertEquals(40, c.samplesSpent());
        assertEquals(3, calls, "8, 8, then the 4 left to the cap");
        assertThrows(IllegalArgumentException.class, () -> new Convergence(1, 1, -0.1, 10));
        assertThrows(IllegalArgumentException.class, () -> new Convergence(1, 1, 0.1, 0));
    }

    @ParameterizedTest
    @EnumSource(value = LightTransport.class, names = {"PATH", "BDPT"})
    void aPixelLeftOutIsNotTracedAndStartsNoPath(LightTransport transport) {
        RenderScene compiled = RenderScene.compile(Renders.scene(SKY_AND_FLOOR),
                new RenderSettings(Shading.COOK_TORRANCE, 6, 0.01, 1e-9).withTransport(transport));
        int w = 16, h = 12;
        try (Tracer tracer = new Tracer(2)) {
            FrameBuffer frame = new FrameBuffer(w, h);
            tracer.traceOnly(new boolean[w * h]);
            tracer.renderPasses(compiled, frame, 64, 0, 4, 4);
            assertEquals(0, tracer.raysCast(), "no pixel traced: not one ray");
            assertArrayEquals(new float[3 * w * h], frame.rgb(), "and the frame as it was");
            boolean[] one = new boolean[w * h];
            one[9 * w + 5] = true; // on the floor
            tracer.traceOnly(one);
            Arrays.fill(frame.rgb(), -1);
            tracer.renderPasses(compiled, frame, 64, 0, 4, 4);
            assertTrue(tracer.raysCast() > 0);
            assertTrue(frame.get(5, 9, 0) >= 0, "the pixel traced is written");
            if (transport == LightTransport.PATH) { // bdpt's light paths may splat onto others
                for (int p = 0; p < w * h; p++) {
                    if (p != 9 * w + 5) {
                        assertEquals(-1f, frame.rgb()[3 * p], "pixel " + p + " untouched");
                    }
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(value = LightTransport.class, names = {"PATH", "BDPT"})
    void theSameSamplesAndBytesAtAnyThreadCountAndTileSize(LightTransport transport) {
        RenderScene compiled = RenderScene.compile(Renders.scene(SKY_AND_FLOOR),
                new RenderSettings(Shading.COOK_TORRANCE, 6, 0.01, 1e-9).withTransport(transport));
        int w = 24, h = 18;
        float[] reference = null;
        int[] referenceSamples = null;
        for (int threads : new int[] {1, 2, 7}) {
            for (int divider : new int[] {1, 8, 13}) {
                Convergence c = new Convergence(w, h, 0.03, 160);
                FrameBuffer frame = new FrameBuffer(w, h);
                try (Tracer tracer = new Tracer(threads)) {
                    c.refine(tracer, compiled, frame, divider, () -> { });
                }
                c.writeAverage(frame);
                int[] samples = new int[w * h];
                for (int p = 0; p < samples.length; p++) {
                    samples[p] = c.samples(p);
                }
                if (reference == null) {
                    reference = frame.rgb().clone();
                    referenceSamples = samples;
                    assertEquals(64, c.fewestSamples(), "the sky stops at the minimum");
                    assertEquals(160, c.passes(), "the ball's edge goes on to the cap");
                }
                assertArrayEquals(referenceSamples, samples, transport + ", " + threads + " threads, divider " + divider);
                assertArrayEquals(reference, frame.rgb(), transport + ", " + threads + " threads, divider " + divider);
            }
        }
    }

    @Test
    void atTheCapWithoutAThresholdTheRefinementIsTheUniformStill() {
        RenderScene compiled = RenderScene.compile(Renders.scene(SKY_AND_FLOOR),
                new RenderSettings(Shading.COOK_TORRANCE, 6, 0.01, 1e-9).withTransport(LightTransport.PATH));
        int w = 16, h = 12;
        Convergence c = new Convergence(w, h, 0, 64);
        FrameBuffer frame = new FrameBuffer(w, h), still = new FrameBuffer(w, h);
        try (Tracer tracer = new Tracer(2)) {
            c.refine(tracer, compiled, frame, 4, () -> { });
            tracer.render(compiled, still, 64, 0, 4);
        }
        c.writeAverage(frame);
        for (int i = 0; i < still.rgb().length; i++) {
            assertEquals(still.rgb()[i], frame.rgb()[i], 1e-6 * Math.max(1, still.rgb()[i]), "value " + i);
        }
    }
}
