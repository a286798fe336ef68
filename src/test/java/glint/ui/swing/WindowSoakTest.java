package glint.ui.swing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.image.Srgb;
import glint.ui.Poll;
import glint.ui.capture.Screenshots;
import glint.ui.scenes.SceneSource;
import glint.ui.screen.ShownFrame;
import java.awt.GraphicsEnvironment;
import java.awt.Point;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.condition.EnabledIf;
import org.junit.jupiter.api.io.TempDir;

/**
 * Load: the real window, 800x600, flown by java.awt.Robot key presses for ten minutes (W/A/S/D, turns,
 * rolls, Shift, mouse drags and wheel, shading and depth keys, and each minute a screenshot, a scene file
 * rewritten in place, F5 and a window resize). After each minute the flight pauses until the window is
 * idle, the heap is collected and its use recorded; at the end the heap after the last minute must be
 * within {@link #HEAP_GROWTH_LIMIT_MB} of the heap after the first.
 *
 * <p>No frame may be torn. Every render gets its own stamp: the sky's colour (0, 0, b) with a blue code
 * that changes from one render to the next, on a scene whose objects have no blue at all (red and green
 * matte, ambient light, no highlights). A checker in front of the display looks at every new image
 * handed over: each pixel with no red and no green is sky and must have the blue of the render that made
 * the image (for a still image, of the average of its sample passes, worked out as the engine does). A
 * frame with tiles from two renders, or from an earlier one, fails. The checker also re-reads each image
 * when the next one arrives: an image must never change after it is handed over.
 *
 * <p>Not part of {@code mvn verify} (tag {@code soak}); run it with
 * {@code xvfb-run -a -s "-screen 0 1600x1200x24" mvn -B -Psoak test} (docs/reliability.md).
 * {@code -Dglint.soak.minutes=N} shortens or lengthens it.
 */
@Tag("soak")
@EnabledIf("hasDisplay")
class WindowSoakTest {

    private static final int W = 800;
    private static final int H = 600;
    private static final int MINUTES = Integer.getInteger("glint.soak.minutes", 10);
    /** The heap after the last minute may exceed that after the first by this much, at most. */
    static final double HEAP_GROWTH_LIMIT_MB = 8;

    @TempDir
    Path dir;

    private GlintWindow window;
    private Robot robot;
    private Path sceneFile;
    private final StringWriter err = new StringWriter();

    static boolean hasDisplay() {
        return !GraphicsEnvironment.isHeadless();
    }

    /** Red, yellow and green matte objects without highlights: no object pixel has any blue. */
    static String scene(double sphereX) {
        return String.format(Locale.ROOT, """
                camera: {position: [0, 1.2, -7], look_at: [0, 1, 0]}
                background: [0, 0, 0.5]
                ambient: [0.1, 0.1, 0.1]
                lights:
                  - {type: point, position: [-4, 7, -5], intensity: 120}
                  - {type: directional, direction: [0.3, -1, 0.4], intensity: 0.8}
                materials:
                  red:    {type: matte, color: [0.8, 0.05, 0], ks: 0}
                  yellow: {type: matte, color: [0.7, 0.6, 0], ks: 0}
                  green:  {type: matte, color: [0.1, 0.6, 0], ks: 0}
                objects:
                  - {type: sphere, center: [%s, 1, 0], radius: 1, material: red}
                  - {type: sphere, center: [-2.6, 0.8, 1.5], radius: 0.8, material: yellow}
                  - {type: sphere, center: [2.4, 0.6, -1], radius: 0.6, material: green}
                  - {type: sphere, center: [1, 2.8, 4], radius: 0.7, material: red}
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: green}
                """, sphereX);
    }

    private record Minute(int minute, double heapMb, long images, long moving, long passes, long torn) {
    }

    @Test
    @Timeout(value = 60, unit = TimeUnit.MINUTES)
    void tenMinutesOfFlightWithoutAGrowingHeapOrATornFrame() throws Exception {
        for (int code = SoakFrames.STAMP_FIRST; code < SoakFrames.STAMP_FIRST + SoakFrames.STAMPS; code++) {
            assertEquals(code, Srgb.to8Bit((float) SoakFrames.linear(code)), "stamp " + code);
        }
        Files.deleteIfExists(Path.of("target", "soak-report.txt"));
        sceneFile = Files.writeString(dir.resolve("soak.yaml"), scene(0));
        Config config = Config.defaults().withSize(W, H).withThreads(2);
        SoakFrames.StampingTrace trace = new SoakFrames.StampingTrace();
        SoakFrames.CheckingPresenter[] checker = new SoakFrames.CheckingPresenter[1];
        window = GlintWindow.open(config, new SceneSource(sceneFile, () -> config), new Screenshots(dir),
                new PrintWriter(err, true),
                new WindowHooks(trace, display -> checker[0] = new SoakFrames.CheckingPresenter(display, trace)));
        trace.engine(window.engine());
        robot = new Robot();
        List<Minute> minutes = new ArrayList<>();
        try {
            Poll.until(() -> window.frame().isShowing() && idle(),
                    30_000, () -> "the first refined frame; err: " + err);
            focus();
            long flightNanos = 0;
            for (int minute = 1; minute <= MINUTES; minute++) {
                long start = System.nanoTime();
                long movingBefore = trace.movingFrames;
                perMinuteChores(minute);
                while (System.nanoTime() - start < 60_000_000_000L) {
                    flyOneRound(start);
                }
                flightNanos += System.nanoTime() - start;
                assertTrue(trace.movingFrames - movingBefore > 100,
                        "minute " + minute + ": the keys flew the camera (" + (trace.movingFrames - movingBefore)
                                + " moving frames); err: " + err);
                Poll.until(this::idle, 30_000, "idle after minute " + minute);
                Minute m = new Minute(minute, usedHeapAfterGc(), checker[0].images, trace.movingFrames,
                        trace.stillPasses, checker[0].torn);
                minutes.add(m);
                report(String.format(Locale.ROOT, "soak: minute %d: heap %.1f MB used after GC; frames %d (moving %d,"
                        + " still passes %d); torn %d; changed after hand-over %d", m.minute(), m.heapMb(), m.images(),
                        m.moving(), m.passes(), m.torn(), checker[0].changedAfterHandover));
            }
            SoakFrames.CheckingPresenter c = checker[0];
            double growth = minutes.get(minutes.size() - 1).heapMb() - minutes.get(0).heapMb();
            report(String.format(Locale.ROOT, "soak: %.1f min of flight; %d frames handed over (%d presents), %d with"
                    + " sky checked (%.1f %%), %d sky pixels checked; torn %d; changed after hand-over %d;"
                    + " heap growth minute 1 to %d: %+.1f MB (limit %.0f MB); max heap %d MB",
                    flightNanos / 60e9, c.images, c.presents, c.imagesWithSky, 100.0 * c.imagesWithSky / c.images,
                    c.skyPixels, c.torn, c.changedAfterHandover, MINUTES, growth, HEAP_GROWTH_LIMIT_MB,
                    Runtime.getRuntime().maxMemory() >> 20));
            assertEquals(0, c.torn, () -> "torn frames: " + c.problems);
            assertEquals(0, c.changedAfterHandover, () -> "images changed after hand-over: " + c.problems);
            assertTrue(c.imagesWithSky > 0.95 * c.images, "the check saw sky in almost every frame");
            assertTrue(window.engineAlive());
            assertTrue(growth <= HEAP_GROWTH_LIMIT_MB, "the heap grew by " + growth + " MB: " + minutes);
            String errors = err.toString();
            assertFalse(errors.contains("render failed") || errors.contains("unexpected") || errors.contains("\tat ")
                    || errors.contains(sceneFile.toString()), () -> "errors on err:\n" + errors);
        } finally {
            window.close();
            assertEquals(0, window.awaitExit());
        }
    }

    // ---- the flight ----

    /** One round of the scripted flight, about 20 s; stops early when the minute is over. */
    private void flyOneRound(long minuteStart) throws Exception {
        List<ThrowingStep> steps = List.of(
                () -> hold(1500, KeyEvent.VK_W), () -> pause(400),
                () -> hold(600, KeyEvent.VK_D), () -> hold(700, KeyEvent.VK_RIGHT), () -> pause(300),
                () -> hold(1500, KeyEvent.VK_S), () -> hold(600, KeyEvent.VK_A), () -> hold(700, KeyEvent.VK_LEFT),
                () -> pause(900), // still long enough to refine to the end and go idle
                () -> hold(300, KeyEvent.VK_SHIFT, KeyEvent.VK_W), () -> hold(1200, KeyEvent.VK_S),
                () -> hold(400, KeyEvent.VK_Q), () -> hold(400, KeyEvent.VK_E),
                () -> hold(250, KeyEvent.VK_UP), () -> hold(250, KeyEvent.VK_DOWN),
                () -> hold(300, KeyEvent.VK_R), () -> hold(300, KeyEvent.VK_F), () -> pause(300),
                () -> drag(120), () -> pause(200), () -> drag(-120),
                () -> robot.mouseWheel(-1), () -> hold(500, KeyEvent.VK_W), () -> robot.mouseWheel(1),
                () -> hold(600, KeyEvent.VK_S), () -> pause(300),
                () -> tap(KeyEvent.VK_M), () -> hold(800, KeyEvent.VK_A), () -> hold(800, KeyEvent.VK_D),
                () -> tap(KeyEvent.VK_M), () -> pause(500),
                () -> tap(KeyEvent.VK_EQUALS), () -> pause(300), () -> tap(KeyEvent.VK_MINUS), () -> pause(300),
                () -> hold(2000, KeyEvent.VK_LEFT, KeyEvent.VK_W), () -> hold(2000, KeyEvent.VK_RIGHT, KeyEvent.VK_S));
        for (ThrowingStep step : steps) {
            if (System.nanoTime() - minuteStart >= 60_000_000_000L) {
                return;
            }
            step.run();
        }
    }

    /** Once a minute: a screenshot, the scene file rewritten in place, F5, a resize and back. */
    private void perMinuteChores(int minute) throws Exception {
        tap(KeyEvent.VK_F12);
        Files.writeString(sceneFile, scene(minute % 2 == 0 ? 0 : 0.4)); // truncated, then written: in place
        pause(1200); // the watcher loads it once it stays the same
        tap(KeyEvent.VK_F5); // the camera goes back to the file's: the flight stays near the objects
        SwingUtilities.invokeAndWait(() -> window.frame().setSize(window.frame().getWidth() + 80,
                window.frame().getHeight() + 60));
        pause(800);
        SwingUtilities.invokeAndWait(() -> window.frame().setSize(window.frame().getWidth() - 80,
                window.frame().getHeight() - 60));
        pause(500);
        focus();
    }

    @FunctionalInterface
    private interface ThrowingStep {
        void run() throws Exception;
    }

    private void hold(long millis, int... keys) throws InterruptedException {
        for (int key : keys) {
            robot.keyPress(key);
        }
        Thread.sleep(millis); // the script's own timing: how long the keys are held
        for (int i = keys.length - 1; i >= 0; i--) {
            robot.keyRelease(keys[i]);
        }
    }

    private void tap(int key) {
        robot.keyPress(key);
        robot.keyRelease(key);
    }

    private static void pause(long millis) throws InterruptedException {
        Thread.sleep(millis); // the script's own timing: time to refine before the next keys
    }

    private void drag(int dx) throws Exception {
        Point p = Poll.onEventThread(() -> window.display().getLocationOnScreen());
        int x = p.x + W / 2;
        int y = p.y + H / 2;
        robot.mouseMove(x, y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        for (int i = 1; i <= 12; i++) {
            robot.mouseMove(x + dx * i / 12, y + i % 3);
            Thread.sleep(15);
        }
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
    }

    /** Clicks into the view so that it has the keyboard focus. */
    private void focus() throws Exception {
        if (window.display().isFocusOwner()) {
            return;
        }
        Point p = Poll.onEventThread(() -> window.display().getLocationOnScreen());
        robot.mouseMove(p.x + W / 2, p.y + H / 2);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        Poll.until(() -> window.display().isFocusOwner(), 10_000, () -> "the keyboard focus; err: " + err);
    }

    // ---- measuring ----

    private boolean idle() {
        ShownFrame f = window.display().shown();
        return f != null && f.image() != null && f.stats().refined() && Double.isNaN(f.stats().fps())
                && f.stats().viewWidth() == W && f.stats().viewHeight() == H;
    }

    private static double usedHeapAfterGc() throws InterruptedException {
        for (int i = 0; i < 3; i++) {
            System.gc();
            Thread.sleep(300);
        }
        return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed() / 1048576.0;
    }

    private static void report(String line) throws IOException {
        System.out.println(line);
        Path file = Path.of("target", "soak-report.txt");
        Files.createDirectories(file.getParent());
        Files.writeString(file, line + System.lineSeparator(), java.nio.file.StandardOpenOption.CREATE,
                java.nio.file.StandardOpenOption.APPEND);
    }
}
