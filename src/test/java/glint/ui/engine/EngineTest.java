package glint.ui.engine;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.image.FrameBuffer;
import glint.image.ImageWriter;
import glint.image.ViewTransform;
import glint.input.InputException;
import glint.math.Vector3d;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Shading;
import glint.render.Tracer;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import glint.ui.FakeClock;
import glint.ui.RecordingPresenter;
import glint.ui.TestScenes;
import glint.ui.capture.Screenshots;
import glint.ui.input.Action;
import glint.ui.input.CameraController;
import glint.ui.input.InputState;
import glint.ui.scenes.SceneSource;
import glint.ui.screen.FrameStats;
import glint.ui.screen.ShownFrame;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The engine loop driven step by step with a fake clock: which frame it renders when, what it shows,
 * and what each command does. No display needed.
 */
class EngineTest {

    private static final int W = 64;
    private static final int H = 48;

    @TempDir
    Path dir;

    private final FakeClock clock = new FakeClock();
    private final InputState input = new InputState(clock, W, H);
    private final RecordingPresenter presenter = new RecordingPresenter();
    private final StringWriter errText = new StringWriter();
    private Config config;
    private Config reloadedConfig;
    private Path sceneFile;
    private Engine engine;

    @BeforeEach
    void start() throws IOException, InputException {
        config = Config.defaults().withSize(W, H).withSamples(4).withThreads(2);
        reloadedConfig = config;
        sceneFile = dir.resolve("scene.yaml");
        Files.writeString(sceneFile, TestScenes.sphere(0.1, 0.2, 0.3));
        SceneSource source = new SceneSource(sceneFile, () -> reloadedConfig);
        engine = new Engine(config, source.loadScene(), source, input, presenter, new Screenshots(dir), clock,
                new PrintWriter(errText, true));
    }

    @AfterEach
    void stop() {
        engine.close();
    }

    private FrameStats lastStats() {
        return presenter.last().stats();
    }

    private void refine() {
        while (engine.step() != Engine.IDLE) {
            clock.advance(0.01);
        }
    }

    /**
     * The exposure keys and T change the picture at once, by encoding the frame on screen again: no pass is
     * traced (the refinement stays complete), and the overlay shows the view transform.
     */
    @Test
    void exposureAndToneKeysEncodeTheFrameOnScreenAgain() {
        refine();
        BufferedImage before = presenter.last().image();
        assertEquals("exposure 0  tone neutral", lastStats().view());
        input.command(Action.EXPOSURE_UP);
        input.command(Action.EXPOSURE_UP);
        assertEquals(Engine.IDLE, engine.step(), "nothing traced: the refinement is complete");
        assertEquals(4, lastStats().samplesDone());
        assertEquals("exposure +1  tone neutral", lastStats().view());
        BufferedImage brighter = presenter.last().image();
        int lighter = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int a = before.getRGB(x, y) & 0xff, b = brighter.getRGB(x, y) & 0xff;
                assertTrue(b >= a, "pixel " + x + "," + y + " darker a stop up");
                lighter += b > a ? 1 : 0;
            }
        }
        assertTrue(lighter > W * H / 2, "most pixels lighter: " + lighter);
        input.command(Action.TOGGLE_TONE);
        input.command(Action.EXPOSURE_DOWN);
        input.command(Action.EXPOSURE_DOWN);
        assertEquals(Engine.IDLE, engine.step());
        assertEquals("exposure 0  tone standard", lastStats().view());
        FrameBuffer still = new FrameBuffer(W, H);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(RenderScene.compile(engine.scene(), config.renderSettings()), still, 4, 0, 8);
        }
        BufferedImage standard = ImageWriter.toImage(still, ViewTransform.STANDARD);
        BufferedImage shown = presenter.last().image();
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                for (int shift = 0; shift <= 16; shift += 8) {
                    int d = Math.abs((standard.getRGB(x, y) >> shift & 0xff) - (shown.getRGB(x, y) >> shift & 0xff));
                    assertTrue(d <= 1, "the standard curve's still image, at pixel " + x + "," + y);
                }
            }
        }
    }

    @Test
    void stillViewRefinesToTheStillImageThenIdles() throws InputException {
        for (int pass = 1; pass <= 4; pass++) {
            assertEquals(0, engine.step(), "renders at once");
            FrameStats s = lastStats();
            assertEquals(pass, s.samplesDone());
            assertEquals(W, s.renderWidth());
            assertEquals(H, s.renderHeight());
            assertFalse(s.moving());
        }
        BufferedImage refined = presenter.last().image();
        int framesBefore = presenter.frames().size();
        assertEquals(Engine.IDLE, engine.step(), "nothing left to do");
        assertEquals(framesBefore + 1, presenter.frames().size(), "shown once more, to say idle");
        assertTrue(lastStats().refined());
        assertTrue(Double.isNaN(lastStats().fps()));
        assertEquals(Engine.IDLE, engine.step());
        assertEquals(framesBefore + 1, presenter.frames().size(), "idle: no more frames");

        // the average of the passes is the 4-sample still image (to within float rounding)
        Scene scene = SceneLoader.load(sceneFile);
        FrameBuffer still = new FrameBuffer(W, H);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(RenderScene.compile(scene, config.renderSettings()), still, 4, 0, 8);
        }
        BufferedImage expected = ImageWriter.toImage(still, config.view()); // the same view transform as a PNG's
        int differing = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int a = expected.getRGB(x, y);
                int b = refined.getRGB(x, y);
                for (int shift = 0; shift <= 16; shift += 8) {
                    int d = Math.abs((a >> shift & 0xff) - (b >> shift & 0xff));
                    assertTrue(d <= 1, "pixel " + x + "," + y);
                    differing += d;
                }
            }
        }
        assertTrue(differing < W * H / 100, "codes off by one: " + differing);
    }

    /**
     * A click focuses the lens on the point under the mouse, its distance along the view direction: the
     * view's centre meets the ball (radius 1, 4 ahead) 3 ahead; a click on the sky leaves the focus. A
     * pinhole keeps the focus silently, without drawing anew.
     */
    @Test
    void aClickFocusesOnThePointUnderTheMouseAndTheOverlayShowsTheLens() {
        refine();
        assertEquals(4, engine.camera().focus(), 1e-12, "the file's camera: focused on its look_at");
        String before = lastStats().message();
        int frames = presenter.frames().size();
        input.focusAt(W / 2.0 - 0.5, H / 2.0 - 0.5); // the pixel whose centre is the view's centre
        assertEquals(Engine.IDLE, engine.step(), "a pinhole's picture does not depend on its focus");
        assertEquals(3, engine.camera().focus(), 1e-9);
        assertEquals(frames, presenter.frames().size());
        assertEquals(before, lastStats().message());
        assertEquals("", lastStats().lens(), "a pinhole: no lens on the overlay");
        input.command(Action.APERTURE_WIDER);
        engine.step();
        assertEquals(3.0 / 64, engine.camera().aperture(), 1e-15);
        assertEquals("aperture 0.0469  focus 3", lastStats().lens());
        refine();
        input.focusAt(0, 0); // above the horizon, beside the ball: the sky
        engine.step();
        assertEquals(3, engine.camera().focus(), 1e-9, "the sky leaves the focus");
        assertEquals("nothing under the mouse to focus on; aperture 0.0469  focus 3", lastStats().message());
    }

    @Test
    void movingRendersCheapFramesAndMovesBySpeedTimesTime() {
        refine();
        Vector3d before = engine.camera().position();
        input.press(Action.FORWARD);
        clock.advance(0.5);
        assertEquals(0, engine.step());
        FrameStats s = lastStats();
        assertTrue(s.moving());
        assertEquals(1, s.samplesDone());
        assertEquals(W / 2, s.renderWidth(), "display_scale 2: starts at half resolution");
        Vector3d moved = engine.camera().position().sub(before);
        assertEquals(config.moveSpeed() * 0.5, moved.length(), 1e-9);
        assertEquals(1, moved.normalize().dot(engine.camera().orientation().forward()), 1e-12);

        clock.advance(0.25);
        input.release(Action.FORWARD);
        assertEquals(0, engine.step());
        assertEquals(config.moveSpeed() * 0.75, engine.camera().position().sub(before).length(), 1e-9);

        // just after the key is up the view waits a moment before refining (no flicker between drags)
        clock.advance(0.01);
        long wait = engine.step();
        assertTrue(wait > 0 && wait <= Engine.MOTION_HOLD_NANOS, "waits " + wait);
        clock.advance(wait / 1e9);
        assertEquals(0, engine.step());
        assertFalse(lastStats().moving());
        assertEquals(W, lastStats().renderWidth(), "full resolution once still");
        assertEquals(1, lastStats().samplesDone(), "and the refinement starts over");
    }

    @Test
    void eachFrameIsANewImage() {
        engine.step();
        engine.step();
        List<ShownFrame> frames = presenter.frames();
        assertNotEquals(System.identityHashCode(frames.get(0).image()), System.identityHashCode(frames.get(1).image()));
        assertTrue(frames.get(1).serial() > frames.get(0).serial());
    }

    @Test
    void shadingAndDepthKeys() {
        refine();
        input.command(Action.TOGGLE_SHADING);
        input.command(Action.DEPTH_UP);
        input.command(Action.DEPTH_UP);
        engine.step();
        assertEquals(Shading.PHONG, lastStats().shading());
        assertEquals(config.recursionMax() + 2, lastStats().depth());
        assertEquals(1, lastStats().samplesDone(), "a changed setting starts the refinement over");
        for (int i = 0; i < 100; i++) {
            input.command(Action.DEPTH_DOWN);
        }
        input.command(Action.TOGGLE_SHADING);
        engine.step();
        assertEquals(1, lastStats().depth(), "depth stays at least 1");
        assertEquals(Shading.COOK_TORRANCE, lastStats().shading());
    }

    @Test
    void screenshotWritesTheViewAsShown() throws IOException {
        refine();
        input.command(Action.SCREENSHOT);
        engine.step();
        List<Path> files;
        try (var list = Files.list(dir)) {
            files = list.filter(p -> p.getFileName().toString().matches("glint-\\d{8}-\\d{6}-\\d{3}\\.png")).toList();
        }
        assertEquals(1, files.size(), "one timestamped PNG: " + files);
        assertTrue(lastStats().message().startsWith("saved "), lastStats().message());
        BufferedImage saved = ImageIO.read(files.get(0).toFile());
        BufferedImage shown = presenter.last().image();
        assertArrayEquals(shown.getRGB(0, 0, W, H, null, 0, W), saved.getRGB(0, 0, W, H, null, 0, W));
    }

    @Test
    void screenshotOfAMovingFrameIsScaledToTheWindow() throws IOException {
        input.press(Action.FORWARD);
        clock.advance(0.1);
        engine.step();
        assertEquals(W / 2, presenter.last().image().getWidth());
        input.command(Action.SCREENSHOT);
        clock.advance(0.1);
        engine.step();
        Path file;
        try (var list = Files.list(dir)) {
            file = list.filter(p -> p.toString().endsWith(".png")).findFirst().orElseThrow();
        }
        BufferedImage saved = ImageIO.read(file.toFile());
        assertEquals(W, saved.getWidth());
        assertEquals(H, saved.getHeight());
    }

    @Test
    void unwritableScreenshotFolderIsAMessageNotACrash() throws IOException, InputException {
        Path notAFolder = Files.writeString(dir.resolve("file"), "x");
        java.util.Map<Path, String> whys = java.util.Map.of(
                dir.resolve("missing"), dir.resolve("missing") + ": no such folder",
                notAFolder, notAFolder + ": Not a directory");
        for (Path folder : whys.keySet()) {
            SceneSource source = new SceneSource(sceneFile, () -> config);
            Engine e = new Engine(config, source.loadScene(), source, input, presenter, new Screenshots(folder),
                    clock, new PrintWriter(errText, true));
            try {
                e.step();
                input.command(Action.SCREENSHOT);
                e.step();
                String message = lastStats().message();
                assertEquals("screenshot not saved: " + whys.get(folder), message);
                assertTrue(errText.toString().contains(message), errText.toString());
                assertFalse(errText.toString().contains("\tat "), "no stack trace");
            } finally {
                e.close();
            }
        }
        if (Files.isDirectory(dir.resolve("missing"))) {
            throw new AssertionError("no folder is created");
        }
    }

    @Test
    void watchedSceneChangesKeepTheUsersViewUnlessItsCameraChanged() throws InputException {
        refine();
        input.press(Action.RIGHT);
        clock.advance(1);
        engine.step();
        input.release(Action.RIGHT);
        Vector3d flown = engine.camera().position();

        Scene bluer = SceneLoader.parse(sceneFile.toString(), TestScenes.sphere(0.1, 0.2, 0.9));
        engine.loaded(bluer);
        engine.step();
        assertEquals(bluer, engine.scene());
        assertEquals(flown, engine.camera().position(), "the same camera in the file: the view stays");
        assertTrue(lastStats().message().startsWith("reloaded "));

        Scene moved = SceneLoader.parse(sceneFile.toString(),
                TestScenes.sphere(0.1, 0.2, 0.9).replace("[0, 1, -4]", "[0, 1, -6]"));
        engine.loaded(moved);
        engine.step();
        assertEquals(new Vector3d(0, 1, -6), engine.camera().position(), "the file's camera changed: it wins");
    }

    @Test
    void aBrokenSceneKeepsTheLastGoodOneAndShowsTheError() {
        refine();
        Scene good = engine.scene();
        InputException broken = new InputException(sceneFile.toString(), 3, 7, "expected a number");
        engine.failed(broken);
        engine.step();
        assertEquals(good, engine.scene());
        assertEquals(sceneFile + ":3:7: expected a number", engine.error());
        assertEquals(engine.error(), lastStats().error());
        assertTrue(errText.toString().contains(engine.error()));
    }

    @Test
    void reloadKeyReadsConfigAndSceneAgainAndResetsTheCamera() throws IOException {
        refine();
        input.press(Action.FORWARD);
        clock.advance(1);
        engine.step();
        input.release(Action.FORWARD);
        reloadedConfig = config.withShading(Shading.PHONG).withRecursionMax(2).withSamples(1);
        Files.writeString(sceneFile, TestScenes.sphere(0.5, 0.5, 0.5));
        input.command(Action.RELOAD);
        clock.advance(1);
        engine.step();
        assertEquals(new Vector3d(0, 1, -4), engine.camera().position());
        assertEquals(new Vector3d(0.5, 0.5, 0.5), engine.scene().background());
        FrameStats s = lastStats();
        assertEquals(Shading.PHONG, s.shading());
        assertEquals(2, s.depth());
        assertEquals(1, s.samplesTotal());
        assertEquals("", s.error());
        assertEquals(config.name(), presenter.title());
    }

    @Test
    void aBrokenConfigOnReloadIsShownAndTheRestStays() throws IOException {
        refine();
        SceneSource source = new SceneSource(sceneFile, () -> {
            throw new InputException("my.properties", 2, 1, "samples: expected a perfect square");
        });
        Engine e = new Engine(config, engine.scene(), source, input, presenter, new Screenshots(dir), clock,
                new PrintWriter(errText, true));
        try {
            input.command(Action.RELOAD);
            e.step();
            assertEquals("my.properties:2:1: samples: expected a perfect square", e.error());
            assertEquals(4, lastStats().samplesTotal());
        } finally {
            e.close();
        }
    }

    @Test
    void resizingRendersAtTheNewSize() {
        refine();
        input.resize(100, 30);
        engine.step();
        assertEquals(100, lastStats().renderWidth());
        assertEquals(30, lastStats().renderHeight());
        assertEquals(100, lastStats().viewWidth());
    }

    @Test
    void wheelChangesTheSpeedShown() {
        refine();
        input.wheel(-1);
        engine.step();
        assertEquals(config.moveSpeed() * CameraController.WHEEL_FACTOR, lastStats().speed(), 1e-12);
    }

    @Test
    void quitEndsTheLoop() throws InterruptedException {
        Thread loop = new Thread(engine);
        loop.start();
        input.command(Action.QUIT);
        loop.join(30_000);
        assertFalse(loop.isAlive());
        assertFalse(engine.isRunning());
        assertTrue(engine.awaitFinished(0, java.util.concurrent.TimeUnit.SECONDS), "finished when its thread ended");
    }
}
