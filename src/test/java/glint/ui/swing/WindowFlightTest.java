package glint.ui.swing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.math.Vector3d;
import glint.scene.Camera;
import glint.scenefile.SceneLoader;
import glint.ui.Poll;
import glint.ui.TestScenes;
import glint.ui.capture.Screenshots;
import glint.ui.input.Action;
import glint.ui.input.CameraController;
import glint.ui.scenes.SceneSource;
import java.awt.GraphicsEnvironment;
import java.awt.Robot;
import java.awt.event.KeyEvent;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIf;
import org.junit.jupiter.api.io.TempDir;

/**
 * Exploring in the real window (Xvfb in CI), keys sent by java.awt.Robot: the views of keys 1 to 9, Home,
 * L, Page Down and Page Up, and the camera block of key C. Skipped without a display.
 */
@EnabledIf("hasDisplay")
class WindowFlightTest {

    private static final int W = 240;
    private static final int H = 180;
    private static final String VIEWS = """
            views:
              - {name: from the left, position: [-4, 1, 0], look_at: [0, 1, 0], fov: 50}
              - {position: [0, 6, -3], look_at: [0, 1, 0], fov: 70}
            """;

    @TempDir
    Path dir;

    private Path first;
    private Path second;
    private GlintWindow window;
    private Robot robot;
    private final StringWriter err = new StringWriter();
    private final StringWriter out = new StringWriter();

    static boolean hasDisplay() {
        return !GraphicsEnvironment.isHeadless();
    }

    @BeforeEach
    void open() throws Exception {
        first = Files.writeString(dir.resolve("a-first.yaml"), TestScenes.sphere(0.1, 0.2, 0.3) + VIEWS);
        second = Files.writeString(dir.resolve("b-second.yaml"), TestScenes.sphere(0.3, 0.2, 0.1)
                .replace("position: [0, 1, -4]", "position: [0, 2, -7]"));
        Config config = Config.defaults().withSize(W, H).withSamples(1).withThreads(2);
        window = GlintWindow.open(config, new SceneSource(first, () -> config), new Screenshots(dir),
                new PrintWriter(err, true));
        window.engine().printTo(new PrintWriter(out, true));
        robot = new Robot();
        Poll.until(() -> window.frame().isShowing() && window.display().shown() != null,
                20_000, () -> "the window shows a frame; err: " + err);
        Poll.clickToFocus(window, robot, () -> "the keyboard focus; err: " + err);
    }

    @AfterEach
    void close() throws InterruptedException {
        if (window != null) {
            window.close();
            assertEquals(0, window.awaitExit());
        }
        assertFalse(err.toString().contains("\tat "), () -> "stack trace on err:\n" + err);
    }

    private void tap(int keyCode) {
        robot.keyPress(keyCode);
        robot.keyRelease(keyCode);
    }

    private static boolean near(Camera a, Camera b, double tolerance) {
        return a.position().sub(b.position()).length() <= tolerance
                && a.orientation().forward().sub(b.orientation().forward()).length() <= tolerance
                && a.orientation().up().sub(b.orientation().up()).length() <= tolerance
                && Math.abs(a.fovDegrees() - b.fovDegrees()) <= tolerance;
    }

    private void awaitCamera(Camera expected, String what) throws InterruptedException {
        Poll.until(() -> near(window.engine().camera(), expected, 1e-12), 10_000,
                () -> what + ": camera " + window.engine().camera() + ", expected " + expected + "; err: " + err);
    }

    private void awaitMessage(String message) throws InterruptedException {
        Poll.until(() -> window.display().shown().stats().message().equals(message), 5_000,
                () -> "the overlay says " + message + ", not " + window.display().shown().stats().message());
    }

    private static Camera lookAt(double x, double y, double z, double fov) {
        return Camera.lookAt(new Vector3d(x, y, z), new Vector3d(0, 1, 0), Vector3d.UNIT_Y, fov);
    }

    @Test
    void keysOneToNineGoToTheViewsAndHomeBackToTheScenesCamera() throws Exception {
        Camera home = window.engine().scene().camera();
        tap(KeyEvent.VK_2);
        awaitCamera(lookAt(0, 6, -3, 70), "key 2");
        awaitMessage("view 2: view 2");
        tap(KeyEvent.VK_1);
        awaitCamera(lookAt(-4, 1, 0, 50), "key 1");
        awaitMessage("view 1: from the left");
        tap(KeyEvent.VK_3); // there is no third view: the camera stays
        awaitMessage("the scene has 2 views (keys 1 to 2)");
        assertTrue(near(window.engine().camera(), lookAt(-4, 1, 0, 50), 1e-12));
        tap(KeyEvent.VK_HOME);
        awaitCamera(home, "Home");
    }

    @Test
    void lLevelsTheCameraAfterARoll() throws Exception {
        robot.keyPress(KeyEvent.VK_Q);
        Poll.until(() -> Math.abs(CameraController.roll(window.engine().camera().orientation())) > 0.1, 10_000,
                () -> "rolled; err: " + err);
        robot.keyRelease(KeyEvent.VK_Q);
        Poll.until(() -> !window.input().isDown(Action.ROLL_LEFT), 5_000, "Q up");
        tap(KeyEvent.VK_L);
        Poll.until(() -> Math.abs(CameraController.roll(window.engine().camera().orientation())) < 1e-12, 10_000,
                () -> "levelled: roll " + CameraController.roll(window.engine().camera().orientation()));
    }

    @Test
    void pageDownOpensTheNextSceneOfTheFolderAndPageUpThePrevious() throws Exception {
        tap(KeyEvent.VK_PAGE_DOWN);
        awaitCamera(lookAt(0, 2, -7, 60), "Page Down");
        Poll.until(() -> window.display().shown().stats().scene().equals(second.toString()), 5_000,
                () -> "the overlay names " + second + ": " + window.display().shown().stats().scene());
        assertTrue(window.engine().scene().views().isEmpty());
        tap(KeyEvent.VK_PAGE_DOWN); // round to the first
        awaitCamera(lookAt(0, 1, -4, 60), "Page Down round to the first");
        assertEquals(2, window.engine().scene().views().size());
        tap(KeyEvent.VK_PAGE_UP);
        awaitCamera(lookAt(0, 2, -7, 60), "Page Up");
        assertEquals("", window.engine().error());
    }

    @Test
    void theBlockOfKeyCReadBackGivesTheSameCamera() throws Exception {
        robot.keyPress(KeyEvent.VK_RIGHT); // somewhere the scene file does not say
        robot.keyPress(KeyEvent.VK_W);
        Poll.until(() -> window.engine().camera().position().x() > 0.3, 10_000, () -> "flew; err: " + err);
        robot.keyRelease(KeyEvent.VK_W);
        robot.keyRelease(KeyEvent.VK_RIGHT);
        Poll.until(() -> !window.input().isDown(Action.FORWARD) && !window.input().isDown(Action.YAW_RIGHT),
                5_000, "keys up");
        Poll.until(() -> !window.display().shown().stats().moving(), 10_000, "still again");
        Camera now = window.engine().camera();
        tap(KeyEvent.VK_C);
        Poll.until(() -> out.toString().endsWith("\n") && out.toString().contains("fov:"), 5_000,
                () -> "the block on standard output: " + out);
        String block = out.toString();
        assertTrue(block.startsWith("camera:\n  position: ["), block);
        awaitMessage(block.strip()); // the overlay shows it
        Camera read = SceneLoader.parse("pasted.yaml", block).camera();
        assertTrue(near(read, now, 1e-5), "read back " + read + ", was " + now + "\n" + block);
    }
}
