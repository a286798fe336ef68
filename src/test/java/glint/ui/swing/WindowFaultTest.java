package glint.ui.swing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.config.Limits;
import glint.image.FrameBuffer;
import glint.render.RenderScene;
import glint.render.Tracer;
import glint.ui.FakeClock;
import glint.ui.FaultyTrace;
import glint.ui.Poll;
import glint.ui.TestScenes;
import glint.ui.capture.Screenshots;
import glint.ui.engine.Engine;
import glint.ui.frames.FrameRenderer;
import glint.ui.scenes.SceneSource;
import glint.ui.screen.FrameStats;
import glint.ui.screen.OverlayText;
import glint.ui.screen.ShownFrame;
import java.awt.GraphicsEnvironment;
import java.awt.Robot;
import java.awt.event.KeyEvent;
import java.awt.event.WindowEvent;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIf;
import org.junit.jupiter.api.io.TempDir;

/**
 * Faults in the real window (Xvfb in CI; skipped without a display): render workers that throw, and a
 * window resized beyond the frame size limit.
 */
@EnabledIf("hasDisplay")
class WindowFaultTest {

    private static final int W = 320;
    private static final int H = 240;

    @TempDir
    Path dir;

    private GlintWindow window;
    private final StringWriter err = new StringWriter();

    static boolean hasDisplay() {
        return !GraphicsEnvironment.isHeadless();
    }

    private GlintWindow open(Config config, WindowHooks hooks) throws Exception {
        Path scene = Files.writeString(dir.resolve("scene.yaml"), TestScenes.sphere(0.1, 0.2, 0.3));
        window = GlintWindow.open(config, new SceneSource(scene, () -> config), new Screenshots(dir),
                new PrintWriter(err, true), hooks);
        return window;
    }

    @AfterEach
    void close() throws InterruptedException {
        if (window != null) {
            window.close();
            assertEquals(0, window.awaitExit(), "the engine never stopped on an error");
        }
        assertFalse(err.toString().contains("\tat "), () -> "stack trace on err:\n" + err);
        assertFalse(err.toString().contains("unexpected"), () -> "error on err:\n" + err);
    }

    private ShownFrame shown() {
        return window.display().shown();
    }

    /** On a clock the test moves: after each failed try the engine pauses for the retry pause of that clock. */
    @Test
    void tilesThatThrowAreShownAndTheWindowRecoversByItself() throws Exception {
        FaultyTrace trace = new FaultyTrace();
        trace.faults.set(4);
        Config config = Config.defaults().withSize(W, H).withSamples(4).withThreads(2);
        FakeClock clock = new FakeClock();
        open(config, new WindowHooks(trace, p -> p, clock));
        for (int tryNumber = 1; tryNumber <= 4; tryNumber++) {
            int tries = tryNumber;
            Poll.until(() -> trace.calls.get() == tries && clock.waitsLeft().equals(List.of(Engine.RETRY_NANOS)),
                    10_000, () -> "try " + tries + " fails and the engine pauses: waits " + clock.waitsLeft()
                            + "; err: " + err);
            Poll.until(() -> shown() != null && shown().stats().renderError().startsWith("render failed: a render worker"),
                    10_000, () -> "the error in the overlay; err: " + err);
            assertTrue(window.engineAlive());
            clock.advanceNanos(Engine.RETRY_NANOS);
        }
        Poll.until(() -> shown().stats().refined() && shown().image() != null, 20_000,
                "a refined frame, with no key pressed");
        assertEquals("", shown().stats().renderError());
        assertEquals(1, err.toString().lines().filter(l -> l.contains("render failed")).count(), err.toString());
        assertTrue(err.toString().contains("rendering works again after 4 failed tries"), err.toString());
        assertTrue(window.engineAlive());
    }

    @Test
    void resizingBeyondTheLimitRendersSmallerFrames() throws Exception {
        Limits limits = new Limits(100_000, Limits.DEFAULT.maxSceneBytes(), Limits.DEFAULT.maxObjects(),
                Limits.DEFAULT.maxLights(), Limits.DEFAULT.maxRecursion());
        Config config = Config.defaults().withSize(W, H).withSamples(1).withThreads(2).withLimits(limits);
        open(config, new WindowHooks(FrameRenderer.TraceCall.TRACER, p -> p));
        Poll.until(() -> shown() != null && shown().image() != null && shown().stats().refined(),
                20_000, () -> "first frame; err: " + err);
        assertEquals(W * H, shown().image().getWidth() * shown().image().getHeight(), "76,800 pixels: allowed");

        SwingUtilities.invokeAndWait(() -> window.frame().setSize(window.frame().getWidth() + 240,
                window.frame().getHeight() + 180));
        Poll.until(() -> shown().stats().viewWidth() == W + 240 && shown().stats().refined(), 20_000,
                "a refined frame at the new size");
        FrameStats s = shown().stats();
        long pixels = (long) shown().image().getWidth() * shown().image().getHeight();
        assertTrue(pixels <= 100_000 && pixels > 95_000, "as large as allowed, no larger: " + pixels);
        assertEquals("100,000 pixels (max_image_pixels)", s.sizeLimit());
        assertTrue(OverlayText.lines(s).contains(new OverlayText.Line(
                "window too large: rendered at most 100,000 pixels (max_image_pixels)", OverlayText.Tone.NOTE)));
        assertTrue(err.toString().contains("glint: the window is " + (W + 240) + "x" + (H + 180)), err.toString());
    }

    /** A frame that never ends (a room of mirrors at depth 64 without pruning): it ends when the test says. */
    private static final class EndlessTrace implements FrameRenderer.TraceCall {
        final CountDownLatch entered = new CountDownLatch(1);
        final CountDownLatch release = new CountDownLatch(1);

        @Override
        public void trace(Tracer tracer, RenderScene scene, FrameBuffer target, int samples, int pass, int count,
                          int divider) {
            entered.countDown();
            try {
                release.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private void quitWhileAFrameNeverEnds(Runnable quit) throws Exception {
        EndlessTrace endless = new EndlessTrace();
        Config config = Config.defaults().withSize(W, H).withSamples(4).withThreads(2);
        try {
            open(config, new WindowHooks(endless, p -> p));
            assertTrue(endless.entered.await(20, TimeUnit.SECONDS), "the frame began");
            quit.run();
            assertTimeoutPreemptively(Duration.ofSeconds(10), () -> assertEquals(0, window.awaitExit()),
                    () -> "the window ended; err: " + err);
            Poll.until(() -> !window.frame().isDisplayable(), 5_000, () -> "the window disposed; err: " + err);
            window = null;
        } finally {
            endless.release.countDown();
        }
    }

    @Test
    void theCloseButtonEndsTheWindowWhileAFrameNeverEnds() throws Exception {
        quitWhileAFrameNeverEnds(() -> {
            try {
                SwingUtilities.invokeAndWait(() -> window.frame().dispatchEvent(
                        new WindowEvent(window.frame(), WindowEvent.WINDOW_CLOSING)));
            } catch (Exception e) {
                throw new AssertionError(e);
            }
        });
    }

    @Test
    void escEndsTheWindowWhileAFrameNeverEnds() throws Exception {
        quitWhileAFrameNeverEnds(() -> {
            try {
                Robot robot = new Robot();
                Poll.clickToFocus(window, robot, () -> "the keyboard focus; err: " + err);
                robot.keyPress(KeyEvent.VK_ESCAPE);
                robot.keyRelease(KeyEvent.VK_ESCAPE);
            } catch (Exception e) {
                throw new AssertionError(e);
            }
        });
    }

    /** Frames traced as usual until the test holds them: the next one then never ends, until it is released. */
    private static final class HeldTrace implements FrameRenderer.TraceCall {
        volatile boolean hold;
        final CountDownLatch entered = new CountDownLatch(1);
        final CountDownLatch release = new CountDownLatch(1);

        @Override
        public void trace(Tracer tracer, RenderScene scene, FrameBuffer target, int samples, int pass, int count,
                          int divider) {
            if (!hold) {
                FrameRenderer.TraceCall.TRACER.trace(tracer, scene, target, samples, pass, count, divider);
                return;
            }
            entered.countDown();
            try {
                release.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private List<Path> stillParts() {
        try (var files = Files.list(dir)) {
            return files.filter(p -> p.getFileName().toString().matches("\\.scene-.*\\.png\\.[0-9a-f]+\\.part")).toList();
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /**
     * The window closed while a still renders and the engine is held in a frame that never ends: the still is
     * cancelled by the window's end itself, its hidden file deleted before the program ends, and standard error
     * says so once, in the words of any other close (not the guard's "the program ended before the still was
     * written").
     */
    @Test
    void closingTheWindowWhileAFrameNeverEndsCancelsTheStillUnderWayAndSaysSoOnce() throws Exception {
        HeldTrace held = new HeldTrace();
        Config config = Config.defaults().withSize(W, H).withSamples(4096).withThreads(2); // a still of minutes
        try {
            open(config, new WindowHooks(held, p -> p));
            Poll.until(() -> shown() != null, 20_000, () -> "a frame; err: " + err);
            window.input().command(glint.ui.input.Action.RENDER_STILL);
            Poll.until(() -> stillParts().size() == 1, 20_000, () -> "the still's hidden file; err: " + err);
            held.hold = true; // the next refinement pass never ends
            assertTrue(held.entered.await(20, TimeUnit.SECONDS), "a frame held");
            SwingUtilities.invokeAndWait(() -> window.frame().dispatchEvent(
                    new WindowEvent(window.frame(), WindowEvent.WINDOW_CLOSING)));
            assertTimeoutPreemptively(Duration.ofSeconds(10), () -> assertEquals(0, window.awaitExit()),
                    () -> "the window ended; err: " + err);
            assertEquals(List.of(), stillParts(), "the still's hidden file is deleted before the program ends");
            assertEquals(List.of("glint: still cancelled, nothing written (the window closed)"),
                    err.toString().lines().toList());
            window = null;
        } finally {
            held.release.countDown();
        }
    }
}
