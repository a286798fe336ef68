package glint.ui.swing;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.app.Main;
import glint.config.Config;
import glint.math.Vector3d;
import glint.render.RenderScene;
import glint.scene.Camera;
import glint.ui.Poll;
import glint.ui.TestScenes;
import glint.ui.capture.Screenshots;
import glint.ui.input.Action;
import glint.ui.input.CameraController;
import glint.ui.input.OrbitPivot;
import glint.ui.scenes.SceneSource;
import glint.ui.screen.FrameStats;
import glint.ui.screen.ShownFrame;
import java.awt.GraphicsEnvironment;
import java.awt.Point;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowEvent;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIf;
import org.junit.jupiter.api.io.TempDir;

/**
 * The window as a studio, driven as a user would (java.awt.Robot on Xvfb): Enter renders the view to a
 * file with the bytes of the printed headless command, Enter or Esc cancels it, closing the window during
 * it leaves no file; Ctrl + drag orbits, Z zooms. Skipped without a display.
 */
@EnabledIf("hasDisplay")
class WindowStudioTest {

    private static final int W = 240;
    private static final int H = 180;

    @TempDir
    Path dir;

    private Path scene;
    private Path shots;
    private GlintWindow window;
    private Robot robot;
    private final StringWriter err = new StringWriter();
    private final StringWriter out = new StringWriter();

    static boolean hasDisplay() {
        return !GraphicsEnvironment.isHeadless();
    }

    private void open(int samples) throws Exception {
        open(Config.defaults().withSize(W, H).withSamples(samples).withThreads(2), TestScenes.sphere(0.1, 0.2, 0.3));
    }

    private void open(Config config, String sceneText) throws Exception {
        scene = Files.writeString(dir.resolve("ball.yaml"), sceneText);
        shots = Files.createDirectories(dir.resolve("shots"));
        window = GlintWindow.open(config, new SceneSource(scene, () -> config), new Screenshots(shots),
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

    private String message() {
        ShownFrame shown = window.display().shown();
        return shown == null ? "" : shown.stats().message();
    }

    private void awaitMessage(String prefix, long millis) throws InterruptedException {
        Poll.until(() -> message().startsWith(prefix), millis,
                () -> "the overlay says " + prefix + "...: " + message() + "; err: " + err);
    }

    private List<Path> files() throws IOException {
        try (var list = Files.list(shots)) {
            return list.sorted().toList();
        }
    }

    private Point onScreen(int x, int y) throws Exception {
        Point p = Poll.onEventThread(() -> window.display().getLocationOnScreen());
        return new Point(p.x + x, p.y + y);
    }

    @Test
    void enterWritesTheViewWithTheBytesOfThePrintedHeadlessCommand() throws Exception {
        open(4);
        tap(KeyEvent.VK_RIGHT); // a view of the user's own
        tap(KeyEvent.VK_ENTER);
        awaitMessage("still: wrote ", 60_000);
        List<Path> written = files();
        assertEquals(1, written.size(), written::toString);
        Path png = written.get(0);
        assertTrue(message().endsWith(png.toString()), message());
        Poll.until(() -> out.toString().contains("fov: "), 5_000, out::toString);
        String printed = out.toString();
        assertTrue(printed.startsWith("still: wrote " + png + " (240x180, 4 spp, cook-torrance, depth 16)"), printed);
        Matcher command = Pattern.compile("java -jar target/glint.jar (.*) --output \\S+\n").matcher(printed);
        assertTrue(command.find(), printed);
        String text = Files.readString(scene);
        Path pasted = Files.writeString(dir.resolve("pasted.yaml"),
                printed.substring(printed.indexOf("camera:\n")) + text.substring(text.indexOf('\n') + 1));
        Path headless = dir.resolve("headless.png");
        String args = command.group(1).replace("--scene " + scene, "--scene " + pasted) + " --config "
                + Files.writeString(dir.resolve("empty.properties"), "") + " --output " + headless;
        StringWriter mainErr = new StringWriter();
        assertEquals(0, Main.run(args.split(" "), new PrintWriter(new StringWriter(), true),
                new PrintWriter(mainErr, true)), mainErr::toString);
        assertArrayEquals(Files.readAllBytes(headless), Files.readAllBytes(png), "the window's still and the headless one");
    }

    @Test
    void shiftEnterWritesAPfmBesideThePng() throws Exception {
        open(1);
        robot.keyPress(KeyEvent.VK_SHIFT);
        tap(KeyEvent.VK_ENTER);
        robot.keyRelease(KeyEvent.VK_SHIFT);
        awaitMessage("still: wrote ", 60_000);
        List<Path> written = files();
        assertEquals(2, written.size(), written::toString);
        Path png = written.get(1);
        assertTrue(png.toString().endsWith(".png") && written.get(0).toString().equals(
                png.toString().replace(".png", ".pfm")), written::toString);
        assertEquals(W, glint.image.PfmReader.read(written.get(0)).width());
        assertTrue(message().endsWith(png + " and " + written.get(0)), message());
    }

    /** A plain click focuses the lens on the ball under the mouse (3 ahead); ] widens the aperture a step. */
    @Test
    void aClickFocusesTheLensAndABracketWidensIt() throws Exception {
        String lens = TestScenes.sphere(0.1, 0.2, 0.3).replace("look_at: [0, 1, 0]}", "look_at: [0, 1, 0], aperture: 0.1}");
        assertTrue(lens.contains("aperture"), lens);
        open(Config.defaults().withSize(W, H).withSamples(1).withThreads(2), lens);
        click(onScreen(W / 2, H - 2)); // the floor, nearer than the ball: 2.35 ahead
        Poll.until(() -> window.engine().camera().focus() < 2.6, 10_000,
                () -> "focused on the floor: " + window.engine().camera() + "; err: " + err);
        click(onScreen(W / 2, H / 2));
        Poll.until(() -> Math.abs(window.engine().camera().focus() - 3) < 0.01, 10_000,
                () -> "focused on the ball's front: " + window.engine().camera() + "; err: " + err);
        awaitMessage("aperture 0.1  focus 3", 10_000);
        tap(KeyEvent.VK_CLOSE_BRACKET);
        Poll.until(() -> Math.abs(window.engine().camera().aperture() - 0.1 * Math.sqrt(2)) < 1e-12, 10_000,
                () -> "] widened the aperture: " + window.engine().camera() + "; err: " + err);
        assertEquals(0, window.engine().camera().position().sub(new glint.math.Vector3d(0, 1, -4)).length(), 1e-12,
                "a click does not move the camera");
    }

    private void click(Point at) {
        robot.mouseMove(at.x, at.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
    }

    @Test
    void aMiddleButtonDragOrbitsToo() throws Exception {
        open(1);
        Camera before = window.engine().camera();
        Point start = onScreen(W / 2, H / 2);
        robot.mouseMove(start.x, start.y);
        robot.mousePress(InputEvent.BUTTON2_DOWN_MASK);
        for (int dx = 10; dx <= 60; dx += 10) {
            robot.mouseMove(start.x - dx, start.y);
        }
        robot.mouseRelease(InputEvent.BUTTON2_DOWN_MASK);
        Poll.until(() -> window.engine().camera().position().x() > before.position().x() + 0.3, 10_000,
                () -> "a drag left circles the camera to the right: " + window.engine().camera() + "; err: " + err);
        assertEquals(0, CameraController.roll(window.engine().camera().orientation()), 1e-12);
    }

    @Test
    void enterOrEscCancelsAndClosingTheWindowDuringAStillLeavesNoFile() throws Exception {
        open(4096); // a still that takes long enough to stop
        tap(KeyEvent.VK_ENTER);
        awaitMessage("still: rendering", 10_000);
        tap(KeyEvent.VK_ENTER);
        awaitMessage("still: cancelled, nothing written", 30_000);
        tap(KeyEvent.VK_ENTER);
        awaitMessage("still: rendering", 10_000);
        tap(KeyEvent.VK_ESCAPE);
        awaitMessage("still: cancelled, nothing written", 30_000);
        assertTrue(window.engineAlive(), "Esc cancelled the still; the window stays");
        assertEquals(List.of(), files());
        tap(KeyEvent.VK_ENTER);
        awaitMessage("still: rendering", 10_000);
        SwingUtilities.invokeAndWait(() -> window.frame().dispatchEvent(
                new WindowEvent(window.frame(), WindowEvent.WINDOW_CLOSING)));
        assertEquals(0, window.awaitExit());
        window = null;
        assertEquals(List.of(), files(), "no image and no hidden part file");
        assertFalse(out.toString().contains("wrote"), out::toString);
    }

    /**
     * Enter, Enter, Enter, 100 ms apart, as a new user tries it: start, cancel, start. The still is one tile
     * (screen_divider=1) of seconds, still being traced after the cancel; the third Enter starts a new still
     * all the same, and it is written.
     */
    @Test
    void threeEntersAHundredMillisecondsApartStartCancelAndStartAStillThatIsWritten() throws Exception {
        open(Config.defaults().withSize(W, H).withSamples(1).withThreads(2).withScreenDivider(1),
                TestScenes.sphere(0.1, 0.2, 0.3) + "render: {samples: 256}\n");
        Poll.until(() -> window.display().shown().stats().refined(), 30_000, "refined");
        tap(KeyEvent.VK_ENTER);
        Thread.sleep(100); // the user's pace
        tap(KeyEvent.VK_ENTER);
        Thread.sleep(100);
        tap(KeyEvent.VK_ENTER);
        awaitMessage("still: wrote ", 120_000);
        List<Path> written = files();
        assertEquals(1, written.size(), written::toString);
        assertEquals(1, out.toString().split("still: wrote ", -1).length - 1, out::toString);
    }

    /**
     * Esc while the overlay says a still is under way never quits: here the overlay says so (a frame handed
     * to the display as the engine would) while no still runs, as when one ends just before the key.
     */
    @Test
    void escWhileTheOverlaySaysAStillIsUnderWayNeverQuits() throws Exception {
        open(1);
        Poll.until(() -> window.display().shown().stats().refined(), 30_000, "refined");
        ShownFrame shown = window.display().shown();
        FrameStats s = shown.stats();
        window.display().present(new ShownFrame(shown.image(), new FrameStats(s.fps(), s.msPerFrame(),
                s.renderWidth(), s.renderHeight(), s.viewWidth(), s.viewHeight(), s.samplesDone(), s.samplesTotal(),
                s.moving(), s.threads(), s.shading(), s.depth(), s.speed(), s.scene(),
                "still: rendering 99 % (Enter or Esc cancels)", s.error(), s.sizeLimit(), s.renderError()),
                shown.serial()));
        tap(KeyEvent.VK_ESCAPE);
        tap(KeyEvent.VK_M); // a key after it: once the engine says so, the Esc was taken
        awaitMessage("shading phong", 10_000);
        assertTrue(window.engineAlive(), "Esc cancelled what the overlay showed; the window stays");
        assertEquals(List.of(), files(), "and started nothing");
    }

    /** A 3840x2160 still (the scene's render: block): Esc while its PNG is written stops the write; nothing is left. */
    @Test
    void escWhileALargeStillIsWrittenStopsTheWriteAndLeavesNothing() throws Exception {
        open(Config.defaults().withSize(W, H).withSamples(1).withThreads(2),
                TestScenes.sphere(0.1, 0.2, 0.3) + "render: {width: 3840, height: 2160}\n");
        tap(KeyEvent.VK_ENTER);
        awaitMessage("still: writing ", 60_000);
        tap(KeyEvent.VK_ESCAPE);
        awaitMessage("still: cancelled, nothing written", 10_000);
        assertEquals(List.of(), files(), "no image, no hidden file");
        assertTrue(window.engineAlive(), "Esc cancelled the still; the window stays");
        window.close();
        assertEquals(0, window.awaitExit());
        window = null;
        assertEquals(List.of(), files());
        assertFalse(out.toString().contains("wrote"), out::toString);
    }

    /** Closing the window while a 3840x2160 PNG is written: the write stops, nothing is left, and standard error says so. */
    @Test
    void closingTheWindowWhileALargeStillIsWrittenLeavesNothingAndSaysSo() throws Exception {
        open(Config.defaults().withSize(W, H).withSamples(1).withThreads(2),
                TestScenes.sphere(0.1, 0.2, 0.3) + "render: {width: 3840, height: 2160}\n");
        tap(KeyEvent.VK_ENTER);
        awaitMessage("still: writing ", 60_000);
        SwingUtilities.invokeAndWait(() -> window.frame().dispatchEvent(
                new WindowEvent(window.frame(), WindowEvent.WINDOW_CLOSING)));
        assertEquals(0, window.awaitExit());
        window = null;
        assertEquals(List.of(), files(), "no image and no hidden file");
        assertTrue(err.toString().contains("glint: still cancelled, nothing written (the window closed)\n"),
                err::toString);
        assertFalse(out.toString().contains("wrote"), out::toString);
    }

    @Test
    void ctrlDragOrbitsRoundThePointUnderTheMouseAndZZooms() throws Exception {
        open(1);
        Camera before = window.engine().camera();
        int x = W / 2 - 20;
        int y = H / 2 + 10;
        RenderScene compiled = RenderScene.compile(window.engine().scene(), Config.defaults().renderSettings());
        Vector3d pivot = OrbitPivot.pick(compiled, before, x, y, W, H);
        assertTrue(pivot.sub(new Vector3d(0, 1, 0)).length() < 1 + 1e-9, "on the ball: " + pivot);
        Point start = onScreen(x, y);
        robot.mouseMove(start.x, start.y);
        robot.keyPress(KeyEvent.VK_CONTROL);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        for (int dx = 10; dx <= 80; dx += 10) {
            robot.mouseMove(start.x + dx, start.y - dx / 4);
        }
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        robot.keyRelease(KeyEvent.VK_CONTROL);
        double distance = before.position().sub(pivot).length();
        Poll.until(() -> {
            Camera c = window.engine().camera();
            return c.position().x() < before.position().x() - 0.5 && c.position().y() < before.position().y();
        }, 10_000, () -> "orbited: " + window.engine().camera() + "; err: " + err);
        Poll.until(() -> !window.display().shown().stats().moving(), 10_000, "still again");
        Camera after = window.engine().camera();
        assertEquals(distance, after.position().sub(pivot).length(), 1e-9, "the same distance from the point");
        assertEquals(0, CameraController.roll(after.orientation()), 1e-12, "the horizon stays level");

        robot.keyPress(KeyEvent.VK_Z);
        Poll.until(() -> window.engine().camera().fovDegrees() < 40, 10_000,
                () -> "zoomed in: fov " + window.engine().camera().fovDegrees());
        robot.keyRelease(KeyEvent.VK_Z);
        Poll.until(() -> !window.input().isDown(Action.ZOOM_IN), 5_000, "Z up");
        assertEquals(after.position(), window.engine().camera().position(), "zoom does not move the camera");
    }
}
