package glint.app;

import glint.config.Config;
import glint.config.Flags;
import glint.config.JarCommand;
import glint.input.InputException;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import glint.ui.capture.Screenshots;
import glint.ui.scenes.ConfigSource;
import glint.ui.scenes.SceneSource;
import glint.ui.swing.GlintWindow;
import java.awt.AWTError;
import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.io.PrintWriter;
import java.nio.file.Path;

/** Opens the interactive window (docs/window.md), or explains in one line why it cannot. */
final class WindowLauncher {

    private WindowLauncher() {
    }

    /** The window on a scene whose config cannot be read again (F5 reloads the scene only). */
    static int open(Path scenePath, Config config, PrintWriter err) throws InputException {
        return open(scenePath, config, Flags.NONE, () -> config, new PrintWriter(System.out, true), err);
    }

    /**
     * Opens the window and returns the exit status when it is closed: 0 when the user quits, 1 when
     * there is no display, or when something the window printed (key C's camera, a still's report)
     * could not be written to {@code out}. A scene that does not load throws before any window opens, and
     * before a missing display is reported.
     *
     * @param flags  the command line's settings, above each scene's render: block
     * @param reload reads the config again for F5
     */
    static int open(Path scenePath, Config config, Flags flags, ConfigSource reload, PrintWriter out, PrintWriter err)
            throws InputException {
        return open(scenePath, null, config, flags, reload, out, err);
    }

    /** {@link #open(Path, Config, Flags, ConfigSource, PrintWriter, PrintWriter)} with the config file read, if any. */
    static int open(Path scenePath, Path configFile, Config config, Flags flags, ConfigSource reload, PrintWriter out,
                    PrintWriter err) throws InputException {
        if (GraphicsEnvironment.isHeadless()) {
            checkInputs(scenePath, config, flags); // bad input says so (status 2), display or not
            return noDisplay(err, "no display available for the window");
        }
        if (Runtime.getRuntime().maxMemory() < LEAST_WINDOW_HEAP) { // it would run out, or crawl on collecting
            err.println(Main.OUT_OF_MEMORY);
            return Main.FAILURE;
        }
        GlintWindow window;
        try {
            window = GlintWindow.open(config, new SceneSource(scenePath, reload, flags, configFile),
                    new Screenshots(Path.of("").toAbsolutePath()), out, err);
        } catch (GlintWindow.UnavailableException e) {
            return noDisplay(err, "cannot open the window (" + e.getMessage() + ")");
        } catch (AWTError | HeadlessException e) {
            return noDisplay(err, "cannot open the window (" + e.getMessage() + ")");
        }
        Thread hook = new Thread(() -> { // SIGTERM, SIGHUP, Ctrl-C: a still under way stops and says so
            try {
                window.interrupt(Interrupts.WAIT_MILLIS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "glint-interrupt");
        Runtime.getRuntime().addShutdownHook(hook);
        try {
            int status = window.awaitExit();
            return status == Main.OK && printingFailed(out) ? Main.FAILURE : status; // the window said so at the time
        } catch (InterruptedException e) {
            window.close();
            Thread.currentThread().interrupt();
            return Main.FAILURE;
        } finally {
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException e) {
                // the program is stopping: the hook runs
            }
        }
    }

    /**
     * The least Java heap (-Xmx) the window opens in. Measured on a 320 x 240 window of a ball on a floor:
     * at -Xmx12m it ran out of memory before or during its first frames in 3 of 3 starts (and at -Xmx8m
     * one start in 4 never ended, the collector running on and on), at -Xmx16m it ran in 3 of 3.
     */
    static final long LEAST_WINDOW_HEAP = 16L << 20;

    /** Whether a line printed to {@code out} was lost. */
    private static boolean printingFailed(PrintWriter out) {
        return out instanceof Output checked ? checked.failed() : out.checkError();
    }

    /** What the window would refuse before it opens: a window too large, a scene that does not load or a render: block beyond the limits. */
    private static void checkInputs(Path scenePath, Config config, Flags flags) throws InputException {
        InputException tooLarge = config.sizeRefusal(); // the window's size: the config's, or --width x --height
        if (tooLarge != null) {
            throw tooLarge;
        }
        Scene scene = SceneLoader.load(scenePath, config.limits().scene());
        flags.effective(config, scene.render());
    }

    private static int noDisplay(PrintWriter err, String why) {
        err.println("glint: " + why + "; render a still with "
                + "--output FILE.png (for example: " + JarCommand.java() + " --output out.png)");
        return Main.FAILURE;
    }
}
