package glint.ui.swing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.app.Main;
import glint.ui.TestScenes;
import java.awt.Frame;
import java.awt.GraphicsEnvironment;
import java.awt.event.WindowEvent;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicInteger;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIf;
import org.junit.jupiter.api.io.TempDir;

/** The jar run without --output or --bench: the window, its exit status, or one line without a display. */
class LauncherTest {

    private static final String TITLE = "Glint launcher test";

    @TempDir
    Path dir;

    private Path config;
    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    static boolean hasDisplay() {
        return !GraphicsEnvironment.isHeadless();
    }

    static boolean headless() {
        return GraphicsEnvironment.isHeadless();
    }

    @BeforeEach
    void files() throws IOException {
        Files.writeString(dir.resolve("scene.yaml"), TestScenes.sphere(0.1, 0.2, 0.3));
        config = Files.writeString(dir.resolve("glint.properties"),
                "scene=scene.yaml\nname=" + TITLE + "\ndisplay_width=200\ndisplay_height=150\nthreads=2\n");
    }

    private int run(String... args) {
        return Main.run(args, new PrintWriter(out, true), new PrintWriter(err, true));
    }

    @Test
    @EnabledIf("headless")
    void withoutADisplayOneLinePointsToOutput() {
        assertEquals(Main.FAILURE, run("--config", config.toString()));
        String text = err.toString();
        assertEquals(1, text.lines().count(), text);
        assertTrue(text.contains("no display") && text.contains("--output"), text);
    }

    @Test
    @EnabledIf("hasDisplay")
    void closingTheWindowExitsWithStatusZero() throws Exception {
        AtomicInteger status = new AtomicInteger(-1);
        Thread app = new Thread(() -> status.set(run("--config", config.toString())), "test-main");
        app.start();
        Frame frame = null;
        long deadline = System.nanoTime() + 20_000_000_000L;
        while (frame == null) {
            Optional<Frame> shown = Arrays.stream(Frame.getFrames())
                    .filter(f -> TITLE.equals(f.getTitle()) && f.isShowing()).findFirst();
            if (shown.isPresent()) {
                frame = shown.get();
            } else if (System.nanoTime() > deadline) {
                throw new AssertionError("no window titled '" + TITLE + "'; err: " + err);
            } else {
                Thread.sleep(10);
            }
        }
        Frame window = frame;
        SwingUtilities.invokeAndWait(() -> window.dispatchEvent(new WindowEvent(window, WindowEvent.WINDOW_CLOSING)));
        app.join(20_000);
        assertFalse(app.isAlive());
        assertEquals(Main.OK, status.get(), err::toString);
        assertEquals("", err.toString());
    }

    @Test
    @EnabledIf("hasDisplay")
    void aBrokenSceneStopsBeforeAnyWindow() throws IOException {
        Files.writeString(dir.resolve("scene.yaml"), "objects:\n  - {type: spere}\n");
        assertEquals(Main.BAD_INPUT, run("--config", config.toString()));
        assertTrue(err.toString().startsWith(dir.resolve("scene.yaml") + ":2:"), err.toString());
        assertFalse(Arrays.stream(Frame.getFrames()).anyMatch(f -> TITLE.equals(f.getTitle()) && f.isShowing()));
    }
}
