package glint.ui.swing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.math.Vector3d;
import glint.scene.Camera;
import glint.ui.FakeClock;
import glint.ui.Poll;
import glint.ui.TestScenes;
import glint.ui.capture.Screenshots;
import glint.ui.engine.Engine;
import glint.ui.frames.FrameRenderer;
import glint.ui.input.Action;
import glint.ui.input.CameraController;
import glint.ui.scenes.SceneSource;
import glint.ui.screen.ShownFrame;
import java.awt.GraphicsEnvironment;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowEvent;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIf;
import org.junit.jupiter.api.io.TempDir;

/**
 * The real window on a real display (Xvfb in CI), driven by java.awt.Robot, on a clock the test moves: a
 * key held for a second of that clock flies the camera exactly a second's worth. Skipped without a
 * display, so that {@code mvn verify} passes anywhere.
 */
@EnabledIf("hasDisplay")
class WindowTest {

    private static final int W = 320;
    private static final int H = 240;
    private static final double SPEED = 2;
    private static final double TURN = 60;

    @TempDir
    Path dir;

    private final FakeClock clock = new FakeClock();
    private GlintWindow window;
    private Robot robot;
    private final StringWriter err = new StringWriter();

    static boolean hasDisplay() {
        return !GraphicsEnvironment.isHeadless();
    }

    @BeforeEach
    void open() throws Exception {
        Path scene = Files.writeString(dir.resolve("scene.yaml"), TestScenes.sphere(0.1, 0.2, 0.3));
        Config config = Config.defaults().withSize(W, H).withSamples(4).withThreads(2);
        window = GlintWindow.open(config, new SceneSource(scene, () -> config), new Screenshots(dir),
                new PrintWriter(err, true), new WindowHooks(FrameRenderer.TraceCall.TRACER, p -> p, clock));
        robot = new Robot();
        Poll.until(() -> window.frame().isShowing() && refined(),
                20_000, () -> "the window shows a refined frame; err: " + err);
        Poll.clickToFocus(window, robot, () -> "the keyboard focus; err: " + err);
    }

    @AfterEach
    void close() throws InterruptedException {
        if (window != null) {
            window.close();
            assertEquals(0, window.awaitExit());
        }
        assertFalse(err.toString().contains("\tat "), () -> "stack trace on err:\n" + err);
        assertFalse(err.toString().contains("unexpected"), () -> "error on err:\n" + err);
    }

    // ---- helpers ----

    private boolean refined() {
        ShownFrame f = window.display().shown();
        return f != null && f.image() != null && f.stats().refined() && f.stats().viewWidth() == W;
    }

    /**
     * Holds the key of {@code action} for {@code seconds} of the window's clock, then lets the motion hold
     * pass, and waits until the view is refined from the new camera.
     */
    private void hold(int keyCode, Action action, double seconds) throws InterruptedException {
        Camera before = window.engine().camera();
        BufferedImage shownBefore = window.display().shown().image();
        robot.keyPress(keyCode);
        Poll.until(() -> window.input().isDown(action), 5_000, () -> action + " down; err: " + err);
        clock.advance(seconds);
        robot.keyRelease(keyCode);
        Poll.until(() -> !window.input().isDown(action), 5_000, () -> action + " up; err: " + err);
        Poll.until(() -> !window.engine().camera().equals(before), 5_000, () -> "the camera moved; err: " + err);
        clock.advance(Engine.MOTION_HOLD_NANOS / 1e9); // the camera at rest: the view refines
        window.input().signal();
        Poll.until(() -> refined() && window.display().shown().image() != shownBefore, 20_000,
                () -> "still again; err: " + err);
    }

    private void tap(int keyCode) {
        robot.keyPress(keyCode);
        robot.keyRelease(keyCode);
    }

    private BufferedImage capture() throws Exception {
        Rectangle area = Poll.onEventThread(() -> new Rectangle(window.display().getLocationOnScreen(),
                window.display().getSize()));
        return robot.createScreenCapture(area);
    }

    private static int[] pixels(BufferedImage image) {
        int w = image.getWidth();
        int h = image.getHeight();
        int[] p = image.getRGB(0, 0, w, h, null, 0, w);
        for (int i = 0; i < p.length; i++) {
            p[i] &= 0xffffff;
        }
        return p;
    }

    private static double yawDegrees(Vector3d forward) {
        return Math.toDegrees(Math.atan2(forward.x(), forward.z()));
    }

    // ---- the tests ----

    @Test
    void opensARealWindowOnTheScene() throws Exception {
        assertTrue(window.frame().isShowing());
        assertEquals("Glint", window.frame().getTitle());
        assertEquals(W, window.display().getWidth());
        assertEquals(H, window.display().getHeight());
        assertTrue(window.engineAlive());
    }

    @Test
    void holdingWFliesForwardBySpeedTimesTime() throws Exception {
        Vector3d before = window.engine().camera().position();
        hold(KeyEvent.VK_W, Action.FORWARD, 1);
        Vector3d moved = window.engine().camera().position().sub(before);
        assertEquals(SPEED * 1, moved.z(), 1e-9, "flew " + moved + " in a second");
        assertEquals(0, moved.x(), 1e-9);
        assertEquals(0, moved.y(), 1e-9);
        hold(KeyEvent.VK_W, Action.FORWARD, 0.25);
        assertEquals(SPEED * 1.25, window.engine().camera().position().sub(before).z(), 1e-9, "and a quarter more");
    }

    @Test
    void arrowKeysTurnTheCamera() throws Exception {
        hold(KeyEvent.VK_RIGHT, Action.YAW_RIGHT, 0.75);
        double yaw = yawDegrees(window.engine().camera().orientation().forward());
        assertEquals(TURN * 0.75, yaw, 1e-9, "turned right " + yaw + " degrees");

        hold(KeyEvent.VK_UP, Action.PITCH_UP, 0.5);
        assertEquals(Math.sin(Math.toRadians(TURN * 0.5)), window.engine().camera().orientation().forward().y(), 1e-9,
                "looks up by 30 degrees");
    }

    @Test
    void draggingTheMouseLooksAround() throws Exception {
        Point start = Poll.onEventThread(() -> window.display().getLocationOnScreen());
        robot.mouseMove(start.x + 100, start.y + 120);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        for (int dx = 10; dx <= 100; dx += 10) {
            robot.mouseMove(start.x + 100 + dx, start.y + 120);
        }
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        double expected = 100 * CameraController.DRAG_DEGREES_PER_PIXEL;
        Poll.until(() -> Math.abs(yawDegrees(window.engine().camera().orientation().forward()) - expected) < 1e-6,
                5_000, "turned right by " + expected + " degrees");
    }

    @Test
    void theWindowChangesAsTheCameraMoves() throws Exception {
        BufferedImage first = capture();
        hold(KeyEvent.VK_D, Action.RIGHT, 0.5);
        BufferedImage second = capture();
        int[] a = pixels(first);
        int[] b = pixels(second);
        long differing = 0;
        for (int i = 0; i < a.length; i++) {
            differing += a[i] != b[i] ? 1 : 0;
        }
        assertTrue(differing > a.length / 20, "pixels that changed: " + differing);
    }

    @Test
    void f12WritesAPngOfWhatTheWindowShows() throws Exception {
        tap(KeyEvent.VK_H); // the overlay off: the window is the view alone
        Poll.until(() -> !window.display().overlayVisible(), 5_000, () -> "overlay hidden; err: " + err);
        tap(KeyEvent.VK_F12);
        Poll.until(() -> pngs().size() == 1, 5_000, "a PNG in " + dir);
        Path png = pngs().get(0);
        assertTrue(png.getFileName().toString().matches("glint-\\d{8}-\\d{6}-\\d{3}\\.png"), png.toString());
        BufferedImage saved = ImageIO.read(png.toFile());
        assertEquals(W, saved.getWidth());
        assertEquals(H, saved.getHeight());
        awaitWindowShows(pixels(saved));
        assertTrue(window.display().shown().stats().message().startsWith("saved "));
    }

    /** Waits until the window's pixels are {@code expected}; says where they differ if they never are. */
    private void awaitWindowShows(int[] expected) throws Exception {
        int[][] last = new int[1][];
        try {
            Poll.until(() -> {
                try {
                    last[0] = pixels(capture());
                    return Arrays.equals(expected, last[0]);
                } catch (Exception e) {
                    throw new AssertionError(e);
                }
            }, 5_000, "the window's pixels equal the PNG's");
        } catch (AssertionError e) {
            int differing = 0;
            int first = -1;
            for (int i = 0; i < expected.length; i++) {
                if (expected[i] != last[0][i]) {
                    differing++;
                    first = first < 0 ? i : first;
                }
            }
            throw new AssertionError(e.getMessage() + ": " + differing + " pixels differ, the first at ("
                    + first % W + ", " + first / W + "): PNG " + Integer.toHexString(expected[first]) + ", window "
                    + Integer.toHexString(last[0][first]) + "; window at " + window.frame().getBounds(), e);
        }
    }

    private List<Path> pngs() {
        try (var files = Files.list(dir)) {
            return files.filter(p -> p.toString().endsWith(".png")).toList();
        } catch (IOException e) {
            throw new AssertionError(e);
        }
    }

    @Test
    void resizingRendersAtTheNewSize() throws Exception {
        SwingUtilities.invokeAndWait(() -> window.frame().setSize(window.frame().getWidth() + 80,
                window.frame().getHeight() + 40));
        Poll.until(() -> {
            ShownFrame f = window.display().shown();
            return f.stats().refined() && f.stats().viewWidth() == W + 80 && f.image().getWidth() == W + 80
                    && f.image().getHeight() == H + 40;
        }, 20_000, "a refined frame at the new size");
    }

    @Test
    void closingTheWindowEndsTheEngine() throws Exception {
        SwingUtilities.invokeAndWait(() -> window.frame().dispatchEvent(
                new WindowEvent(window.frame(), WindowEvent.WINDOW_CLOSING)));
        Poll.until(() -> !window.engineAlive(), 10_000, () -> "the engine ended; err: " + err);
        assertEquals(0, window.awaitExit());
        Poll.until(() -> !window.frame().isDisplayable(), 5_000, () -> "the window disposed; err: " + err);
        window = null;
    }

    @Test
    void escapeQuits() throws Exception {
        tap(KeyEvent.VK_ESCAPE);
        Poll.until(() -> !window.engineAlive(), 10_000, () -> "the engine ended; err: " + err);
        assertEquals(0, window.awaitExit());
        window = null;
    }

    @Test
    void helpListsTheKeys() throws Exception {
        BufferedImage before = capture();
        robot.keyPress(KeyEvent.VK_SHIFT);
        tap(KeyEvent.VK_SLASH); // '?' on a US keyboard
        robot.keyRelease(KeyEvent.VK_SHIFT);
        Poll.until(() -> window.display().helpVisible(), 5_000, () -> "the help key; err: " + err);
        int[] a = pixels(before);
        Poll.until(() -> {
            try {
                return !Arrays.equals(a, pixels(capture()));
            } catch (Exception e) {
                throw new AssertionError(e);
            }
        }, 5_000, "the help drawn over the view");
        Optional<ShownFrame> shown = Optional.ofNullable(window.display().shown());
        assertTrue(shown.isPresent());
    }
}
