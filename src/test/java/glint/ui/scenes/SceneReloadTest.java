package glint.ui.scenes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.image.Srgb;
import glint.image.ViewTransform;
import glint.math.Vector3d;
import glint.scene.Scene;
import glint.ui.Poll;
import glint.ui.RecordingPresenter;
import glint.ui.TestScenes;
import glint.ui.capture.Screenshots;
import glint.ui.engine.Engine;
import glint.ui.input.Clock;
import glint.ui.input.InputState;
import glint.ui.screen.OverlayText;
import glint.ui.screen.ShownFrame;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The scene file is watched: a saved file is on screen once the watcher's second read, a period after the
 * first, finds it unchanged; a broken one keeps the last good scene and shows its error. Real files, the
 * engine on its own thread, the watcher's reads when the test says a period passed ({@link ManualTimer}); no
 * display needed.
 */
class SceneReloadTest {

    private static final int W = 32;
    private static final int H = 24;

    @TempDir
    Path dir;

    private Path file;
    private final ManualTimer timer = new ManualTimer();
    private SceneWatcher watcher;
    private Engine engine;
    private Thread loop;
    private final RecordingPresenter presenter = new RecordingPresenter();
    private final StringWriter err = new StringWriter();

    @BeforeEach
    void open() throws Exception {
        file = dir.resolve("scene.yaml");
        Files.writeString(file, TestScenes.sphere(0.1, 0.2, 0.3));
        Config config = Config.defaults().withSize(W, H).withSamples(1).withThreads(2)
                .withView(ViewTransform.STANDARD); // pixels compared with the plain sRGB encoding
        SceneSource source = new SceneSource(file, () -> config);
        watcher = new SceneWatcher(source, timer);
        Scene scene = source.loadScene();
        engine = new Engine(config, scene, source, new InputState(Clock.SYSTEM, W, H), presenter,
                new Screenshots(dir), Clock.SYSTEM, new PrintWriter(err, true));
        loop = new Thread(engine, "test-engine");
        loop.start();
        watcher.start(engine);
        Poll.until(() -> shownBackground() == srgb(0.1, 0.2, 0.3), 10_000, "first frame");
    }

    @AfterEach
    void close() throws InterruptedException {
        watcher.close();
        engine.stop();
        loop.join(30_000);
    }

    /** The top-left pixel of the frame on screen sees the sky. */
    private int shownBackground() {
        ShownFrame f = presenter.last();
        return f == null || f.image() == null ? -1 : f.image().getRGB(0, 0) & 0xffffff;
    }

    private static int srgb(double r, double g, double b) {
        return Srgb.to8Bit(r) << 16 | Srgb.to8Bit(g) << 8 | Srgb.to8Bit(b);
    }

    /** Two periods of the watcher, 500 ms: the first read finds the change, the second loads it. */
    private void twoReads() {
        timer.tick();
        timer.tick();
    }

    @Test
    void aSavedSceneIsOnScreenAfterTwoReadsAPeriodApart() throws Exception {
        Scene first = engine.scene();
        TestScenes.replace(file, TestScenes.sphere(0.9, 0.1, 0.1));
        timer.tick();
        assertEquals(first, engine.scene(), "read once: not loaded yet");
        timer.tick();
        Poll.until(() -> shownBackground() == srgb(0.9, 0.1, 0.1), 5_000, "new background on screen");
        assertEquals(new Vector3d(0.9, 0.1, 0.1), engine.scene().background());

        Files.writeString(file, TestScenes.sphere(0.1, 0.9, 0.1)); // written in place, not renamed
        twoReads();
        Poll.until(() -> shownBackground() == srgb(0.1, 0.9, 0.1), 5_000, "second change on screen");
    }

    @Test
    void aBrokenSceneKeepsTheLastGoodOneAndShowsItsError() throws Exception {
        Scene good = engine.scene();
        TestScenes.replace(file, TestScenes.sphere(0.9, 0.1, 0.1).replace("radius: 1", "radiu: 1"));
        String expected = file + ":6:39: unknown key 'radiu' in sphere (did you mean 'radius'?)";
        twoReads();
        Poll.until(() -> expected.equals(engine.error()), 5_000, "the error");
        Poll.until(() -> presenter.last().stats().error().equals(expected), 5_000, "the error in the overlay");
        assertEquals(good, engine.scene());
        assertEquals(srgb(0.1, 0.2, 0.3), shownBackground(), "the old scene stays on screen");
        assertTrue(err.toString().contains(expected), err.toString());
        assertTrue(OverlayText.lines(presenter.last().stats()).contains(
                new OverlayText.Line(expected, OverlayText.Tone.ERROR)));

        // mended: the error goes, the new scene comes
        TestScenes.replace(file, TestScenes.sphere(0.9, 0.1, 0.1));
        twoReads();
        Poll.until(() -> shownBackground() == srgb(0.9, 0.1, 0.1), 5_000, "mended scene on screen");
        assertEquals("", engine.error());
    }

    @Test
    void aVanishedFileIsAnErrorOnlyIfItStaysAway() throws Exception {
        Scene good = engine.scene();
        Files.delete(file);
        String expected = file + ": no such file";
        twoReads();
        Poll.until(() -> expected.equals(engine.error()), 5_000, "the error");
        assertEquals(good, engine.scene());
        Files.writeString(file, TestScenes.sphere(0.1, 0.2, 0.3));
        twoReads();
        Poll.until(() -> engine.error().isEmpty(), 5_000, "back again");
    }
}
