package glint.ui.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.config.Flags;
import glint.input.InputException;
import glint.scene.Scene;
import glint.ui.FakeClock;
import glint.ui.FaultyTrace;
import glint.ui.RecordingPresenter;
import glint.ui.TestScenes;
import glint.ui.frames.FrameRenderer;
import glint.ui.frames.ResolutionGovernor;
import glint.ui.input.CameraController;
import glint.ui.scenes.SceneSource;
import glint.ui.screen.FrameStats;
import glint.ui.screen.ShownFrame;
import glint.ui.view.FrameSize;
import glint.ui.view.SceneView;
import glint.ui.view.StatusLine;
import glint.ui.view.ViewSettings;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Frames made and shown one at a time, without the engine loop: moving frames and still passes move the
 * refinement on; a failure keeps the last frame, says why once, and sets when to try again.
 */
class FrameMakerTest {

    private static final int W = 32;
    private static final int H = 24;

    @TempDir
    Path dir;

    private final FakeClock clock = new FakeClock();
    private final StringWriter errText = new StringWriter();
    private final PrintWriter err = new PrintWriter(errText, true);
    private final StatusLine status = new StatusLine(err);
    private final RecordingPresenter presenter = new RecordingPresenter();
    private final FaultyTrace trace = new FaultyTrace();
    private SceneView view;
    private FrameMaker maker;

    @BeforeEach
    void open() throws IOException, InputException {
        Config config = Config.defaults().withSize(W, H).withSamples(4).withThreads(2);
        Path file = dir.resolve("scene.yaml");
        Files.writeString(file, TestScenes.sphere(0.1, 0.2, 0.3));
        SceneSource source = new SceneSource(file, () -> config);
        Scene scene = source.loadScene();
        FrameSize size = new FrameSize(W, H, status, err);
        view = new SceneView(new ViewSettings(config, Flags.NONE), new CameraController(scene.camera(), 2, 60),
                size, status);
        view.show(scene, true);
        FrameRenderer renderer = new FrameRenderer(2, 4, trace);
        RenderFaults faults = new RenderFaults();
        FrameOutput frames = new FrameOutput(presenter, view, size, status, source, renderer, faults, err);
        maker = new FrameMaker(renderer, new ResolutionGovernor(30, 1), faults, view, size, frames, status, clock,
                err);
    }

    @AfterEach
    void close() {
        maker.close();
    }

    @Test
    void aMovingFrameThenStillPassesRefineTheView() {
        assertTrue(maker.moving(clock.nanoTime()));
        assertFalse(view.needFrame());
        assertEquals(0, view.passesDone());
        FrameStats moving = presenter.last().stats();
        assertTrue(moving.moving());
        assertEquals(1, moving.samplesDone());

        while (view.passesDone() < 4) {
            clock.advance(0.01);
            assertTrue(maker.pass(clock.nanoTime()));
        }
        FrameStats still = presenter.last().stats();
        assertEquals(4, still.samplesDone());
        assertTrue(still.refined());
        assertEquals(W, still.renderWidth());
        assertEquals("", errText.toString());
    }

    @Test
    void aFailureKeepsTheLastFrameSaysWhyOnceAndIsTriedAgainLater() {
        assertTrue(maker.moving(clock.nanoTime()));
        ShownFrame good = presenter.last();
        trace.faults.set(2);

        long now = clock.nanoTime();
        assertFalse(maker.pass(now));
        assertEquals(now + RenderFaults.RETRY_NANOS, maker.retryAt());
        assertTrue(view.needFrame(), "the refinement starts over");
        assertEquals(0, view.passesDone());
        ShownFrame shown = presenter.last();
        assertEquals(good.image(), shown.image(), "the last good frame stays");
        assertTrue(shown.stats().renderError().startsWith("render failed: "), shown.stats().renderError());

        clock.advance(0.5);
        assertFalse(maker.moving(clock.nanoTime()));
        assertTrue(presenter.last().stats().renderError().endsWith("(2 tries); trying again"),
                presenter.last().stats().renderError());
        assertEquals(1, errText.toString().lines().filter(l -> l.startsWith("glint: render failed")).count(),
                errText.toString());

        clock.advance(0.5);
        assertTrue(maker.moving(clock.nanoTime()));
        assertEquals("rendering works again", status.message());
        assertTrue(errText.toString().contains("glint: rendering works again after 2 failed tries"),
                errText.toString());
        assertEquals("", presenter.last().stats().renderError());
    }

    @Test
    void aFailureOutsideAFrameAlsoStartsTheRefinementOver() {
        assertTrue(maker.moving(clock.nanoTime()));
        assertTrue(maker.pass(clock.nanoTime()));
        assertTrue(view.passesDone() > 0);
        status.shown();
        maker.failed(new IllegalStateException("boom"));
        assertTrue(view.needFrame());
        assertEquals(0, view.passesDone());
        assertTrue(status.isChanged());
        assertTrue(errText.toString().contains("render failed: java.lang.IllegalStateException: boom"),
                errText.toString());
    }
}
