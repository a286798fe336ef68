package glint.ui.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.image.FrameBuffer;
import glint.input.InputException;
import glint.render.LightTransport;
import glint.render.RenderScene;
import glint.render.Tracer;
import glint.ui.FakeClock;
import glint.ui.RecordingPresenter;
import glint.ui.TestScenes;
import glint.ui.capture.Screenshots;
import glint.ui.frames.FrameRenderer;
import glint.ui.input.InputState;
import glint.ui.scenes.SceneSource;
import glint.ui.screen.FrameStats;
import glint.ui.screen.OverlayText;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The window at rest with the path and bdpt integrators stops refining: at the noise threshold, every pixel
 * converged (the overlay says converged), or at max_samples; then the engine idles and traces nothing more,
 * whatever the steps that follow.
 */
class AdaptiveRefinementTest {

    private static final int W = 16, H = 12;

    @TempDir
    Path dir;

    private final FakeClock clock = new FakeClock();
    private final RecordingPresenter presenter = new RecordingPresenter();
    private Engine engine;
    /** Calls to the tracer: passes and moving frames. */
    private int traces;

    private void open(Config config) throws IOException, InputException {
        Path file = dir.resolve("scene.yaml");
        Files.writeString(file, TestScenes.sphere(0.4, 0.5, 0.8));
        SceneSource source = new SceneSource(file, () -> config);
        FrameRenderer.TraceCall counting = (tracer, scene, target, samples, pass, count, divider) -> {
            traces++;
            FrameRenderer.TraceCall.TRACER.trace(tracer, scene, target, samples, pass, count, divider);
        };
        engine = new Engine(config, source.loadScene(), source, new InputState(clock, W, H), presenter,
                new Screenshots(dir), clock, new PrintWriter(new StringWriter(), true), counting);
    }

    @AfterEach
    void close() {
        if (engine != null) {
            engine.close();
        }
    }

    /** Steps until the engine idles; the steps it took. */
    private int refine() {
        int steps = 0;
        while (engine.step() != Engine.IDLE) {
            clock.advance(0.01);
            steps++;
            assertTrue(steps < 10_000, "the refinement ends");
        }
        return steps;
    }

    private void assertIdleForGood() {
        int before = traces, frames = presenter.frames().size();
        for (int i = 0; i < 5; i++) {
            clock.advance(1);
            assertEquals(Engine.IDLE, engine.step());
        }
        assertEquals(before, traces, "idle: nothing traced");
        assertEquals(frames, presenter.frames().size(), "idle: nothing shown");
    }

    private static Config config(LightTransport transport) {
        return Config.defaults().withSize(W, H).withThreads(2).withTransport(transport);
    }

    @Test
    void theCapStopsTheWindow() throws Exception {
        open(config(LightTransport.PATH).withMaxSamples(24).withNoise(1e-4));
        refine();
        FrameStats s = presenter.last().stats();
        assertEquals(24, s.samplesDone());
        assertTrue(s.refined());
        assertFalse(s.converged(), "stopped by the cap, 1e-4 is not reached");
        List<String> lines = OverlayText.lines(s).stream().map(OverlayText.Line::text).toList();
        assertTrue(lines.get(0).startsWith("idle: image complete"), lines.get(0));
        assertTrue(lines.get(2).startsWith("samples 24   noise ") && lines.get(2).endsWith("   at most 24   threads 2"),
                lines.get(2));
        assertIdleForGood();
    }

    @Test
    void everyPixelConvergedStopsTheWindowAndTheOverlaySaysSo() throws Exception {
        // a threshold of 100 %: every pixel converges at the minimum, 64 samples
        open(config(LightTransport.BDPT).withNoise(1));
        refine();
        FrameStats s = presenter.last().stats();
        assertEquals(64, s.samplesDone());
        assertTrue(s.converged());
        assertTrue(s.refined());
        List<String> lines = OverlayText.lines(s).stream().map(OverlayText.Line::text).toList();
        assertTrue(lines.get(0).startsWith("idle: converged"), lines.get(0));
        assertTrue(lines.get(2).endsWith("   converged   threads 2"), lines.get(2));
        assertIdleForGood();
        // the image on screen is the 64-sample still of the same pattern
        FrameBuffer still = new FrameBuffer(W, H);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(RenderScene.compile(engine.scene(), config(LightTransport.BDPT).renderSettings()), still,
                    64, 0, 8);
        }
        java.awt.image.BufferedImage expected = glint.image.ImageWriter.toImage(still,
                config(LightTransport.BDPT).view());
        java.awt.image.BufferedImage shown = presenter.last().image();
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                for (int shift = 0; shift <= 16; shift += 8) {
                    int d = Math.abs((expected.getRGB(x, y) >> shift & 0xff) - (shown.getRGB(x, y) >> shift & 0xff));
                    assertTrue(d <= 1, "pixel " + x + "," + y);
                }
            }
        }
    }

    @Test
    void withoutAThresholdTheWindowRefinesToOnePercent() throws Exception {
        open(config(LightTransport.PATH).withMaxSamples(96));
        refine();
        FrameStats s = presenter.last().stats();
        assertTrue(s.samplesDone() >= 64 && s.samplesDone() <= 96, "stops between the minimum and the cap: "
                + s.samplesDone());
        assertTrue(s.refined());
        assertIdleForGood();
    }
}
