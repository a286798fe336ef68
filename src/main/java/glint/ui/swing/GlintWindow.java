package glint.ui.swing;

import glint.config.Config;
import glint.input.InputException;
import glint.scene.Scene;
import glint.ui.capture.Screenshots;
import glint.ui.engine.Engine;
import glint.ui.frames.RefinePacing;
import glint.ui.input.InputState;
import glint.ui.scenes.SceneSource;
import glint.ui.scenes.SceneWatcher;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.PrintWriter;
import java.lang.reflect.InvocationTargetException;
import java.util.concurrent.TimeUnit;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;

/**
 * The window put together: a frame with the {@link Display}, the {@link Engine} on its own thread, and
 * the {@link SceneWatcher}. {@link #awaitExit} returns when the user quits (Escape) or closes it.
 */
public final class GlintWindow {

    /** The window could not be opened (no usable display); the message says why, in one line. */
    public static final class UnavailableException extends Exception {
        UnavailableException(String message, Throwable cause) {
            super(message, cause);
        }
    }

    private final JFrame frame;
    private final Display display;
    private final Engine engine;
    private final InputState input;
    private final SceneWatcher watcher;
    private final Thread engineThread;

    private GlintWindow(JFrame frame, Display display, Engine engine, InputState input, SceneWatcher watcher) {
        this.frame = frame;
        this.display = display;
        this.engine = engine;
        this.input = input;
        this.watcher = watcher;
        this.engineThread = new Thread(engine, "glint-engine");
    }

    /**
     * Loads the scene and opens the window on it.
     *
     * @throws InputException       the scene does not load, or the config's window is larger than its
     *                              {@code max_image_pixels} (no window is opened)
     * @throws UnavailableException there is no display to open a window on
     */
    public static GlintWindow open(Config config, SceneSource source, Screenshots screenshots, PrintWriter err)
            throws InputException, UnavailableException {
        return open(config, source, screenshots, new PrintWriter(System.out, true), err, WindowHooks.NONE);
    }

    /**
     * {@link #open(Config, SceneSource, Screenshots, PrintWriter)}, key C's camera and the stills' reports
     * printed to {@code out}: a line it cannot take is said in the overlay and on {@code err}.
     */
    public static GlintWindow open(Config config, SceneSource source, Screenshots screenshots, PrintWriter out,
                                   PrintWriter err) throws InputException, UnavailableException {
        return open(config, source, screenshots, out, err, WindowHooks.NONE);
    }

    /** {@link #open(Config, SceneSource, Screenshots, PrintWriter)} with test hooks. */
    static GlintWindow open(Config config, SceneSource source, Screenshots screenshots, PrintWriter err,
                            WindowHooks hooks) throws InputException, UnavailableException {
        return open(config, source, screenshots, new PrintWriter(System.out, true), err, hooks);
    }

    private static GlintWindow open(Config config, SceneSource source, Screenshots screenshots, PrintWriter out,
                                    PrintWriter err, WindowHooks hooks) throws InputException, UnavailableException {
        InputException tooLarge = config.sizeRefusal();
        if (tooLarge != null) { // refused before any memory or window is taken
            throw tooLarge;
        }
        oneLineErrors(err);
        source.limits(config.limits().scene());
        SceneWatcher watcher = new SceneWatcher(source); // before loading: no change is missed
        Scene scene;
        try {
            scene = source.loadScene();
            source.flags().effective(config, scene.render(), err::println); // a block beyond the limits: no window
        } catch (InputException e) {
            watcher.close();
            throw e;
        }
        JFrame[] frame = new JFrame[1];
        Display[] display = new Display[1];
        onEventThread(() -> {
            display[0] = new Display(config.displayWidth(), config.displayHeight());
            frame[0] = new JFrame(config.name());
            frame[0].setDefaultCloseOperation(JFrame.DO_NOTHING_ON_CLOSE);
            frame[0].add(display[0]);
            frame[0].pack();
            frame[0].setLocationByPlatform(true); // the window manager places it; (0, 0) without one
        }, watcher);
        InputState input = new InputState(hooks.clock(), display[0].getWidth(), display[0].getHeight());
        Engine engine = new Engine(config, scene, source, input, hooks.presenter().apply(display[0]), screenshots,
                hooks.clock(), err, hooks.trace());
        engine.paceRefinement(RefinePacing.windowInterval(config.targetFps())); // quick passes: several at once
        engine.printTo(out);
        GlintWindow window = new GlintWindow(frame[0], display[0], engine, input, watcher);
        onEventThread(() -> {
            InputListener.attach(input, display[0], () -> quitIfStuck(engine)); // Esc, even while a frame never ends
            frame[0].addWindowListener(new WindowAdapter() {
                @Override
                public void windowClosing(WindowEvent e) {
                    engine.stop(); // never waits: the engine ends after its frame, then the frame goes
                }
            });
            frame[0].setVisible(true);
            display[0].requestFocusInWindow();
        }, watcher);
        input.resize(display[0].getWidth(), display[0].getHeight());
        window.engineThread.start();
        watcher.start(engine);
        return window;
    }

    public JFrame frame() {
        return frame;
    }

    public Display display() {
        return display;
    }

    public Engine engine() {
        return engine;
    }

    public InputState input() {
        return input;
    }

    /** Whether the engine's thread is still running. */
    public boolean engineAlive() {
        return engineThread.isAlive();
    }

    /**
     * Waits until the user quits or closes the window, closes it, and returns the exit status: 0, or
     * 1 if the engine stopped on an unexpected error.
     */
    public int awaitExit() throws InterruptedException {
        try {
            engine.awaitStopping();
            engineThread.join(QUIT_WAIT_MILLIS); // a frame that never ends is left to the end of the program
            if (engineThread.isAlive()) { // held in it: a still under way is cancelled from here, and said
                engine.abandon();
            }
        } finally {
            close();
        }
        engine.awaitFinished(QUIT_WAIT_MILLIS, TimeUnit.MILLISECONDS);
        return engine.hasFailed() ? 1 : 0;
    }

    /**
     * Esc on the event thread: the engine quits at its next turn (or cancels a still), unless it takes no turn
     * within {@link #QUIT_WAIT_MILLIS}, stuck in a frame; then it is told to stop, and the window ends.
     */
    private static void quitIfStuck(Engine engine) {
        long turn = engine.turns();
        javax.swing.Timer check = new javax.swing.Timer((int) QUIT_WAIT_MILLIS, e -> {
            if (engine.turns() == turn) {
                engine.stop();
            }
        });
        check.setRepeats(false);
        check.start();
    }

    /**
     * How long the window waits, once the user quit or closed it, for the frame under way to end: a frame may
     * never end (a room of mirrors at depth 64 without pruning), and the render threads do not keep the
     * program alive.
     */
    static final long QUIT_WAIT_MILLIS = 500;

    /**
     * The program is being stopped by a signal (a shutdown hook's thread): the engine ends, cancelling a
     * still under way (its hidden files deleted, standard error saying so), within {@code millis}.
     */
    public void interrupt(long millis) throws InterruptedException {
        engine.interrupt();
        watcher.close();
        engine.awaitFinished(millis, TimeUnit.MILLISECONDS);
    }

    /** Stops the engine and the watcher and closes the window (any thread, never waits). */
    public void close() {
        engine.stop();
        watcher.close();
        SwingUtilities.invokeLater(frame::dispose);
    }

    /**
     * An unexpected failure on any thread (the event thread included) is one line, not a stack trace. The
     * program's main has set such a handler already (which also makes the exit status 1); a window opened
     * without it gets this one.
     */
    private static void oneLineErrors(PrintWriter err) {
        Thread.UncaughtExceptionHandler now = Thread.getDefaultUncaughtExceptionHandler();
        if (now == null || now instanceof OneLineErrors) { // none, or a window's before this one
            Thread.setDefaultUncaughtExceptionHandler(new OneLineErrors(err));
        }
    }

    /** A thread's uncaught error as one line on standard error. */
    private record OneLineErrors(PrintWriter err) implements Thread.UncaughtExceptionHandler {
        @Override
        public void uncaughtException(Thread thread, Throwable e) {
            try {
                err.println("glint: unexpected error on " + thread.getName() + ": " + e);
                err.flush();
            } catch (Throwable again) {
                // no memory left even for the line
            }
        }
    }

    private static void onEventThread(Runnable task, SceneWatcher watcher) throws UnavailableException {
        try {
            SwingUtilities.invokeAndWait(task);
        } catch (InvocationTargetException e) {
            watcher.close();
            Throwable cause = e.getCause() != null ? e.getCause() : e;
            String why = cause.getMessage() != null ? cause.getMessage() : cause.toString();
            throw new UnavailableException(why.lines().findFirst().orElse(why), cause);
        } catch (InterruptedException e) {
            watcher.close();
            Thread.currentThread().interrupt();
            throw new UnavailableException("interrupted while opening the window", e);
        }
    }
}
