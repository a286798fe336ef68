package glint.ui.engine;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.config.Limits;
import glint.input.InputException;
import glint.ui.FakeClock;
import glint.ui.FaultyTrace;
import glint.ui.Poll;
import glint.ui.RecordingPresenter;
import glint.ui.TestScenes;
import glint.ui.capture.Screenshots;
import glint.ui.input.Action;
import glint.ui.input.InputState;
import glint.ui.scenes.SceneSource;
import glint.ui.screen.FrameStats;
import glint.ui.screen.OverlayText;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Faults in the window's engine, without a display: a render worker that throws in a tile, memory that
 * runs out, a window larger than the limits, scene limits on reload. The faults are real: the tracer's
 * own worker threads throw (they are handed a scene they cannot read) and the tracer reports it.
 */
class EngineFaultTest {

    private static final int W = 64;
    private static final int H = 48;

    @TempDir
    Path dir;

    private final FakeClock clock = new FakeClock();
    private final InputState input = new InputState(clock, W, H);
    private final RecordingPresenter presenter = new RecordingPresenter();
    private final StringWriter errText = new StringWriter();
    private final FaultyTrace trace = new FaultyTrace();
    private Config config = Config.defaults().withSize(W, H).withSamples(4).withThreads(2);
    private Config reloadedConfig = config;
    private Engine engine;

    /**
     * The tracer, except that while {@code faults} is above zero a frame's tiles throw in the tracer's
     * worker threads (the workers are given no scene: each tile fails with a NullPointerException, which
     * the tracer catches and reports as a RenderException), or {@code error} is thrown as it is.
     */
    private Engine open(Config c) throws IOException, InputException {
        Path sceneFile = dir.resolve("scene.yaml");
        Files.writeString(sceneFile, TestScenes.sphere(0.1, 0.2, 0.3));
        SceneSource source = new SceneSource(sceneFile, () -> reloadedConfig);
        engine = new Engine(c, source.loadScene(), source, input, presenter, new Screenshots(dir), clock,
                new PrintWriter(errText, true), trace);
        return engine;
    }

    @AfterEach
    void close() {
        if (engine != null) {
            engine.close();
        }
    }

    private FrameStats lastStats() {
        return presenter.last().stats();
    }

    /** Whether the engine's loop waits on the clock, and for exactly {@code nanos} of it. */
    private boolean waitsFor(long nanos) {
        return clock.waitsLeft().equals(List.of(nanos));
    }

    private long linesWith(String text) {
        return errText.toString().lines().filter(l -> l.contains(text)).count();
    }

    private static int[] pixels(BufferedImage image) {
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    /** The still image the engine refines to without any fault. */
    private int[] cleanStillImage() throws IOException, InputException {
        RecordingPresenter clean = new RecordingPresenter();
        Path sceneFile = dir.resolve("clean.yaml");
        Files.writeString(sceneFile, TestScenes.sphere(0.1, 0.2, 0.3));
        SceneSource source = new SceneSource(sceneFile, () -> config);
        Engine e = new Engine(config, source.loadScene(), source, new InputState(clock, W, H), clean,
                new Screenshots(dir), clock, new PrintWriter(new StringWriter(), true));
        try {
            while (e.step() != Engine.IDLE) {
                clock.advance(0.01);
            }
        } finally {
            e.close();
        }
        return pixels(clean.last().image());
    }

    @Test
    void aTileThatThrowsIsShownLoggedOnceAndTriedAgainWithoutInput() throws Exception {
        open(config);
        assertEquals(0, engine.step());
        assertEquals(0, engine.step());
        assertEquals(2, lastStats().samplesDone());
        BufferedImage good = presenter.last().image();

        trace.faults.set(5); // the next five tries fail, in the tracer's worker threads
        long wait = engine.step(); // try 1
        assertTrue(wait > 0 && wait <= Engine.RETRY_NANOS, "waits to try again: " + wait);
        assertTrue(engine.isRunning());
        FrameStats s = lastStats();
        assertTrue(s.renderError().startsWith("render failed: a render worker failed: java.lang.NullPointerException"),
                s.renderError());
        assertTrue(s.renderError().endsWith("; trying again"), s.renderError());
        assertSame(good, presenter.last().image(), "the last good frame stays on screen");
        assertTrue(OverlayText.lines(s).contains(new OverlayText.Line(s.renderError(), OverlayText.Tone.ERROR)));

        // no input at all: each step waits out the pause, then tries the frame again
        for (int tryNumber = 2; tryNumber <= 6; tryNumber++) {
            int calls = trace.calls.get();
            assertEquals(Engine.RETRY_NANOS, engine.step(), "during the pause");
            assertEquals(calls, trace.calls.get(), "nothing is traced during the pause");
            clock.advance(wait / 1e9);
            wait = engine.step();
            assertEquals(calls + 1, trace.calls.get(), "tried again, without input");
            if (tryNumber < 6) {
                assertEquals(Engine.RETRY_NANOS, wait);
                assertTrue(lastStats().renderError().contains("(" + tryNumber + " tries)"), lastStats().renderError());
            }
        }
        assertEquals(0, wait, "the sixth try worked");
        assertEquals("", lastStats().renderError());
        assertEquals("rendering works again", lastStats().message());
        assertEquals(1, lastStats().samplesDone(), "a failed pass starts the refinement over");
        assertEquals(1, linesWith("render failed"), "logged once, not once a try:\n" + errText);
        assertEquals(1, linesWith("rendering works again after 5 failed tries"), errText.toString());
        assertFalse(errText.toString().contains("\tat "), "no stack trace");

        while (engine.step() != Engine.IDLE) {
            clock.advance(0.01);
        }
        assertTrue(lastStats().refined());
        assertArrayEquals(cleanStillImage(), pixels(presenter.last().image()),
                "the refined image is exactly the one without faults: no failed pass was averaged in");
    }

    @Test
    void aFaultWhileFlyingIsTriedAgainAndFlyingGoesOn() throws Exception {
        open(config);
        input.press(Action.FORWARD);
        clock.advance(0.1);
        assertEquals(0, engine.step());
        trace.faults.set(1);
        clock.advance(0.1);
        long wait = engine.step();
        assertEquals(Engine.RETRY_NANOS, wait);
        assertFalse(lastStats().renderError().isEmpty());
        clock.advance(0.1);
        assertTrue(engine.step() > 0, "still pausing, though the key is held");
        clock.advance(0.5);
        assertEquals(0, engine.step());
        assertTrue(lastStats().moving());
        assertEquals("", lastStats().renderError());
        assertEquals(config.moveSpeed() * 0.8, engine.camera().position().z() - (-4), 1e-9,
                "the camera flew on through the pause");
    }

    @Test
    void runningOutOfMemoryInAFrameIsAFaultLikeAnyOther() throws Exception {
        open(config);
        trace.error = new OutOfMemoryError("Java heap space");
        trace.faults.set(1);
        assertEquals(Engine.RETRY_NANOS, engine.step());
        assertEquals("render failed: out of memory (Java heap space); trying again", lastStats().renderError());
        clock.advance(0.5);
        assertEquals(0, engine.step());
        assertEquals("", lastStats().renderError());
        assertEquals(1, lastStats().samplesDone());
    }

    @Test
    void theEngineThreadRecoversOnItsOwn() throws Exception {
        open(config);
        trace.faults.set(3);
        Thread loop = new Thread(engine, "test-engine");
        loop.start();
        try {
            for (int tryNumber = 1; tryNumber <= 3; tryNumber++) {
                int tries = tryNumber;
                Poll.until(() -> trace.calls.get() == tries && waitsFor(Engine.RETRY_NANOS), 20_000,
                        () -> "try " + tries + " fails, and the loop pauses: waits " + clock.waitsLeft() + "; err: "
                                + errText);
                assertTrue(lastStats().renderError().endsWith("; trying again"), lastStats().renderError());
                clock.advanceNanos(Engine.RETRY_NANOS - 1);
                assertEquals(List.of(1L), clock.waitsLeft(), "a nanosecond before the pause ends, the loop waits on");
                assertEquals(tries, trace.calls.get(), "not tried again before the pause is over");
                clock.advanceNanos(1);
            }
            Poll.until(() -> presenter.last().stats().refined() && clock.waitsLeft().size() == 1, 20_000,
                    () -> "a refined frame after three failed tries, and the loop idle; err: " + errText);
            assertEquals(3 + 4, trace.calls.get(), "three failed tries, then the four passes of the still, one by one");
            assertTrue(loop.isAlive());
            assertFalse(engine.hasFailed());
            assertEquals(1, linesWith("render failed"), errText.toString());
            assertEquals(1, linesWith("rendering works again after 3 failed tries"), errText.toString());
            assertEquals("", lastStats().renderError());
            assertArrayEquals(cleanStillImage(), pixels(presenter.last().image()));
        } finally {
            engine.stop();
            loop.join(30_000);
        }
        assertFalse(loop.isAlive(), "the loop ended on request");
    }

    @Test
    void aWindowLargerThanTheLimitRendersSmallerAndSaysSo() throws Exception {
        Limits small = new Limits(10_000, Limits.DEFAULT.maxSceneBytes(), Limits.DEFAULT.maxObjects(),
                Limits.DEFAULT.maxLights(), Limits.DEFAULT.maxRecursion());
        config = config.withLimits(small);
        open(config);
        while (engine.step() != Engine.IDLE) {
            clock.advance(0.01);
        }
        assertEquals(W, lastStats().renderWidth(), "64x48 is within the limit");
        assertEquals("", lastStats().sizeLimit());

        input.resize(400, 300);
        engine.step();
        FrameStats s = lastStats();
        assertTrue((long) s.renderWidth() * s.renderHeight() <= 10_000, s.renderWidth() + "x" + s.renderHeight());
        assertTrue(s.renderWidth() >= 114 && s.renderHeight() >= 85, "as large as allowed: " + s.renderWidth()
                + "x" + s.renderHeight());
        assertEquals(400.0 / 300, (double) s.renderWidth() / s.renderHeight(), 0.02, "the window's aspect");
        assertEquals(400, s.viewWidth());
        assertEquals("10,000 pixels (max_image_pixels)", s.sizeLimit());
        assertTrue(s.message().startsWith("the window is 400x300; frames are rendered at "), s.message());
        assertEquals(1, linesWith("the window is 400x300"), errText.toString());

        input.press(Action.FORWARD); // moving frames too
        clock.advance(0.1);
        engine.step();
        input.release(Action.FORWARD);
        assertTrue(lastStats().moving());
        assertTrue((long) lastStats().renderWidth() * lastStats().renderHeight() <= 10_000);

        input.resize(100_000, 75_000); // 7.5 gigapixels: 450 GB of frame buffers if it were taken
        clock.advance(1);
        while (engine.step() != Engine.IDLE) {
            clock.advance(0.01);
        }
        s = lastStats();
        assertTrue(s.refined());
        assertTrue((long) s.renderWidth() * s.renderHeight() <= 10_000, s.renderWidth() + "x" + s.renderHeight());
        assertEquals(1, linesWith("frames are rendered at"), "said once while it binds:\n" + errText);

        input.command(Action.SCREENSHOT); // the largest image allowed, not 100000x75000
        engine.step();
        Path png;
        try (var files = Files.list(dir)) {
            png = files.filter(p -> p.toString().endsWith(".png")).findFirst().orElseThrow();
        }
        BufferedImage saved = ImageIO.read(png.toFile());
        assertEquals(s.renderWidth(), saved.getWidth());
        assertEquals(s.renderHeight(), saved.getHeight());
        assertTrue(lastStats().message().contains("(at most 10,000 pixels (max_image_pixels))"),
                lastStats().message());

        input.resize(W, H);
        while (engine.step() != Engine.IDLE) {
            clock.advance(0.01);
        }
        assertEquals(W, lastStats().renderWidth(), "within the limit again: full size");
        assertEquals("", lastStats().sizeLimit());
    }

    /** docs/window.md's example: a 4000x3000 window under max_image_pixels=20000 saves a 163x122 PNG, and says so. */
    @Test
    void theScreenshotOfAWindowBeyondTheLimitIsTheLargestFrameAllowed() throws Exception {
        config = config.withLimits(new Limits(20_000, Limits.DEFAULT.maxSceneBytes(), Limits.DEFAULT.maxObjects(),
                Limits.DEFAULT.maxLights(), Limits.DEFAULT.maxRecursion()));
        open(config);
        input.resize(4000, 3000);
        clock.advance(1);
        while (engine.step() != Engine.IDLE) {
            clock.advance(0.01);
        }
        input.command(Action.SCREENSHOT);
        engine.step();
        Path png;
        try (var files = Files.list(dir)) {
            png = files.filter(p -> p.toString().endsWith(".png")).findFirst().orElseThrow();
        }
        BufferedImage saved = ImageIO.read(png.toFile());
        assertEquals("163x122", saved.getWidth() + "x" + saved.getHeight());
        assertEquals("saved " + png + " at 163x122 (at most 20,000 pixels (max_image_pixels))", lastStats().message());
    }

    @Test
    void reloadingReadsTheSceneWithinTheReloadedConfigsLimits() throws Exception {
        open(config);
        engine.step();
        Limits oneObject = new Limits(Limits.DEFAULT.maxImagePixels(), Limits.DEFAULT.maxSceneBytes(), 1,
                Limits.DEFAULT.maxLights(), Limits.DEFAULT.maxRecursion());
        reloadedConfig = config.withLimits(oneObject);
        input.command(Action.RELOAD);
        engine.step();
        assertTrue(engine.error().endsWith("too many objects: more than 1 (config key max_objects)"), engine.error());
        assertEquals(2, engine.scene().objects().size(), "the last good scene stays");
    }

    @Test
    void depthKeysStopAtTheConfiguredMaximum() throws Exception {
        Limits shallow = new Limits(Limits.DEFAULT.maxImagePixels(), Limits.DEFAULT.maxSceneBytes(),
                Limits.DEFAULT.maxObjects(), Limits.DEFAULT.maxLights(), 6);
        open(config.withLimits(shallow));
        for (int i = 0; i < 5; i++) {
            input.command(Action.DEPTH_UP);
        }
        engine.step();
        assertEquals(6, lastStats().depth());
        assertEquals("depth stays 6 (from 1 to 6, max_recursion)", lastStats().message());
    }

    @Test
    void anUnwritableScreenshotFolderIsAMessageAndTheWindowGoesOn() throws Exception {
        Path sceneFile = dir.resolve("scene.yaml");
        Files.writeString(sceneFile, TestScenes.sphere(0.1, 0.2, 0.3));
        Path notAFolder = Files.writeString(dir.resolve("not-a-folder"), "x");
        SceneSource source = new SceneSource(sceneFile, () -> config);
        engine = new Engine(config, source.loadScene(), source, input, presenter, new Screenshots(notAFolder),
                clock, new PrintWriter(errText, true), trace);
        engine.step();
        input.command(Action.SCREENSHOT);
        engine.step();
        assertEquals("screenshot not saved: " + notAFolder + ": Not a directory", lastStats().message());
        long framesBefore = presenter.frames().size();
        while (engine.step() != Engine.IDLE) {
            clock.advance(0.01);
        }
        assertTrue(presenter.frames().size() > framesBefore, "frames go on");
        assertTrue(lastStats().refined());
        assertTrue(engine.isRunning());
        assertEquals(List.of(), errText.toString().lines().filter(l -> l.contains("\tat ")).toList());
        assertNotEquals(0, linesWith("screenshot not saved"));
    }
}
