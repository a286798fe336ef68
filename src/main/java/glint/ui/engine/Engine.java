package glint.ui.engine;

import glint.config.Config;
import glint.input.InputException;
import glint.scene.Camera;
import glint.scene.Scene;
import glint.ui.capture.Captures;
import glint.ui.capture.Screenshots;
import glint.ui.capture.StillRender;
import glint.ui.frames.FrameRenderer;
import glint.ui.frames.Refinement;
import glint.ui.frames.ResolutionGovernor;
import glint.ui.input.Action;
import glint.ui.input.CameraController;
import glint.ui.input.Clock;
import glint.ui.input.InputFrame;
import glint.ui.input.InputState;
import glint.ui.input.OrbitPivot;
import glint.ui.scenes.Reloads;
import glint.ui.scenes.SceneBrowser;
import glint.ui.scenes.SceneSource;
import glint.ui.scenes.SceneWatcher;
import glint.ui.screen.Presenter;
import glint.ui.screen.ShownFrame;
import glint.ui.view.FrameSize;
import glint.ui.view.SceneView;
import glint.ui.view.StatusLine;
import glint.ui.view.ViewSettings;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * The window's loop, on its own thread: input, camera update, render, present. While the camera
 * moves it renders one-sample frames at the resolution the {@link ResolutionGovernor} allows; when it
 * is still it renders the full resolution in sample passes that accumulate up to the configured
 * samples, then waits without using the CPU until something changes.
 *
 * <p>{@link #step} is one turn of the loop and is what tests drive with their own clock; {@link #run}
 * repeats it and waits on {@link InputState#awaitActivity} as long as it asks, timed by the same clock.
 *
 * <p>Faults do not end it: a frame that fails to render (a render worker threw, memory ran out) keeps the
 * last good frame on screen, shows why in the overlay, says so once on standard error, and is tried again
 * after {@link RenderFaults#RETRY_NANOS} without waiting for input. A window larger than the config's
 * {@code max_image_pixels} (or than half the heap can hold) is rendered smaller and scaled up.
 *
 * <p>The loop is this class; the rest is in its parts, each on the engine thread unless it says otherwise:
 * {@link SceneView} (the scene, camera, settings, window size and refinement), {@link FrameSize} (the
 * window's size and the frame budget, which the view changes), {@link StatusLine} (the overlay's messages), {@link FrameMaker} (rendering frames, and
 * their faults), {@link FrameOutput} (frames to the presenter), {@link Commands} (the command keys),
 * {@link Captures} (screenshots and stills), {@link SceneBrowser} (Page Down and Page Up) and {@link Reloads}
 * (F5 and the scene watcher's changes).
 */
public final class Engine implements Runnable, SceneWatcher.Listener {

    /** After the last motion the view waits this long before refining, so a drag does not flicker. */
    public static final long MOTION_HOLD_NANOS = 150_000_000L;
    /** What {@link #step} returns when there is nothing to do until the user does something. */
    public static final long IDLE = Long.MAX_VALUE;
    /** After a frame failed to render, it is tried again this much later. */
    public static final long RETRY_NANOS = RenderFaults.RETRY_NANOS;

    private final SceneSource source;
    private final InputState input;
    private final Presenter presenter;
    private final Clock clock;
    private final PrintWriter err;
    private final CountDownLatch finished = new CountDownLatch(1);
    /** Counted down when the loop is asked to end, or ends by itself. */
    private final CountDownLatch stopping = new CountDownLatch(1);

    private final StatusLine status;
    private final FrameSize size;
    private final SceneView view;
    private final FrameOutput frames;
    private final FrameMaker maker;
    private final Captures captures;
    private final Reloads reloads;
    private final Commands commands;
    private long lastMotion;

    private volatile boolean running = true;
    private volatile boolean failed;
    /** Memory held back so that, when the heap is full, there is room to say so. */
    private volatile byte[] reserve = new byte[64 * 1024];
    /** Turns of the loop begun so far. */
    private volatile long turns;
    /** What standard error says if the loop's end cancels a still under way. */
    private volatile String stillCancelled = "glint: still cancelled, nothing written (the window closed)";
    private final java.util.concurrent.locks.ReentrantLock stillEnding = new java.util.concurrent.locks.ReentrantLock();

    public Engine(Config config, Scene scene, SceneSource source, InputState input, Presenter presenter,
                  Screenshots screenshots, Clock clock, PrintWriter err) {
        this(config, scene, source, input, presenter, screenshots, clock, err, FrameRenderer.TraceCall.TRACER);
    }

    /** An engine whose frames are traced by {@code trace} (tests: injected faults, stamped frames). */
    public Engine(Config config, Scene scene, SceneSource source, InputState input, Presenter presenter,
                  Screenshots screenshots, Clock clock, PrintWriter err, FrameRenderer.TraceCall trace) {
        this.source = source;
        this.input = input;
        this.presenter = presenter;
        this.clock = clock;
        this.err = err;
        CameraController controller = new CameraController(scene.camera(), config.moveSpeed(), config.turnSpeed());
        controller.setFreeFlight(config.freeFlight());
        FrameRenderer renderer = new FrameRenderer(config.effectiveThreads(), config.screenDivider(), trace);
        RenderFaults faults = new RenderFaults();
        this.status = new StatusLine(err);
        this.size = new FrameSize(input.viewWidth(), input.viewHeight(), status, err);
        this.view = new SceneView(new ViewSettings(config, source.flags()), controller, size, status);
        this.frames = new FrameOutput(presenter, view, size, status, source, renderer, faults, err);
        this.maker = new FrameMaker(renderer, new ResolutionGovernor(config.targetFps(), config.displayScale()),
                faults, view, size, frames, status, clock, err);
        this.captures = new Captures(screenshots, new StillRender(input::signal), view, size, source,
                frames::lastImage, err);
        this.reloads = new Reloads(source, view, status, this::configure, input::signal);
        this.commands = new Commands(view, status, captures, new SceneBrowser(source, reloads, view, status), reloads,
                this::stop);
        this.lastMotion = clock.nanoTime() - MOTION_HOLD_NANOS - 1;
        source.limits(config.limits().scene());
        view.show(scene, true);
    }

    // ---- what other threads may ask or tell ----

    /** The camera now (any thread). */
    public Camera camera() {
        return view.camera();
    }

    /** The scene on screen: the last one that loaded (any thread). */
    public Scene scene() {
        return view.sceneNow();
    }

    /** The last load error as {@code file:line:col: message}, or empty (any thread). */
    public String error() {
        return status.error();
    }

    /** The last frame handed to the presenter, or null (any thread). */
    public ShownFrame shown() {
        return frames.shown();
    }

    public boolean isRunning() {
        return running;
    }

    /** Whether the loop ended on an unexpected error rather than on request. */
    public boolean hasFailed() {
        return failed;
    }

    /** Asks the loop to end (any thread); it ends after the frame in progress. */
    public void stop() {
        running = false;
        stopping.countDown();
        input.signal();
    }

    /** Turns of the loop begun so far (any thread): one that does not change is stuck in a frame. */
    public long turns() {
        return turns;
    }

    /**
     * Waits until the loop is asked to end ({@link #stop}, Esc) or has ended by itself, however long the frame
     * under way takes.
     */
    public void awaitStopping() throws InterruptedException {
        stopping.await();
    }

    /** The program is being stopped by a signal (any thread): the loop ends, and says so if a still is lost. */
    public void interrupt() {
        stillCancelled = "glint: interrupted; still cancelled, nothing written";
        stop();
    }

    /**
     * The window ends while this engine's thread is held in a frame that never ends (any thread): a still under
     * way is cancelled at once, its hidden files deleted, and standard error says so, once. If the engine's own
     * thread is ending it just then, that thread says it.
     */
    public void abandon() {
        if (stillEnding.tryLock()) {
            try {
                endStill(false);
            } finally {
                stillEnding.unlock();
            }
        }
    }

    /** Cancels a still under way and says so, once whichever thread comes first; waits for its threads if {@code wait}. */
    private void endStill(boolean wait) {
        stillEnding.lock();
        try {
            if (wait ? captures.stop() : captures.cancelNow()) {
                err.println(stillCancelled);
                err.flush();
            }
        } finally {
            stillEnding.unlock();
        }
    }

    /** Where key C prints the camera block (standard output unless a test says otherwise). */
    public void printTo(PrintWriter printer) {
        commands.printTo(printer);
    }

    /**
     * Traces about {@code nanos} of still passes in one go while passes are quicker
     * ({@link glint.ui.frames.RefinePacing}).
     */
    public void paceRefinement(long nanos) {
        maker.paceRefinement(nanos);
    }

    /** Waits until {@link #run} has returned. */
    public boolean awaitFinished(long timeout, TimeUnit unit) throws InterruptedException {
        return finished.await(timeout, unit);
    }

    /** Frees the render threads when the loop was driven by {@link #step} alone (tests). */
    public void close() {
        captures.close();
        maker.close();
    }

    /** The watcher's thread: a new version of the scene file loaded; the engine shows it at its next turn. */
    @Override
    public void loaded(Scene newScene) {
        reloads.loaded(newScene);
    }

    /** The watcher's thread: a new version of the scene file does not load; the engine says why. */
    @Override
    public void failed(InputException problem) {
        reloads.failed(problem);
    }

    /** The watcher's thread: a version of {@code file} loaded; shown unless another scene is open by then. */
    @Override
    public void loaded(Path file, Scene newScene) {
        reloads.loaded(file, newScene);
    }

    /** The watcher's thread: a version of {@code file} does not load; said unless another scene is open by then. */
    @Override
    public void failed(Path file, InputException problem) {
        reloads.failed(file, problem);
    }

    // ---- the loop ----

    @Override
    public void run() {
        try {
            while (running) {
                long wait;
                try {
                    wait = step();
                } catch (RuntimeException | OutOfMemoryError e) {
                    failedFrame(e); // shown and logged once; the frame is tried again
                    wait = RETRY_NANOS;
                }
                if (running && wait > 0) {
                    input.awaitActivity(wait);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (OutOfMemoryError e) {
            failed = true;
            reserve = null;
            throw e; // said once by the program's handler of every thread's errors, with the others
        } catch (Error e) {
            failed = true;
            err.println("glint: the window's engine stopped: " + e);
        } finally {
            running = false;
            stopping.countDown();
            endStill(true); // a still under way is cancelled, and its hidden files deleted, before the end
            maker.close();
            finished.countDown();
        }
    }

    /**
     * A frame failed. When memory runs out even while saying so, the engine goes on (the frame is tried again)
     * and the program's handler of errors says it once when a thread ends on it.
     */
    private void failedFrame(Throwable e) {
        try {
            maker.failed(e);
        } catch (OutOfMemoryError again) {
            reserve = null; // room for the next try, and to say it
        }
    }

    /**
     * One turn of the loop; returns how long to wait for input before the next one (0: go on at
     * once, {@link #IDLE}: until something happens).
     */
    public long step() {
        turns++;
        captures.stillNews().ifPresent(status::note); // a still's progress, or its end
        long wait = stepOnce();
        return captures.stillRunning() ? Math.min(wait, StillRender.POLL_NANOS) : wait; // its progress is shown
    }

    private long stepOnce() {
        long start = clock.nanoTime();
        InputFrame in = input.drain();
        for (Action command : in.commands()) {
            if (!command.jumpsCamera()) {
                commands.run(command, in);
            }
        }
        if (!running) {
            return 0;
        }
        if (view.takeRetoned()) { // the exposure or the tone: the frame on screen encoded again, not traced again
            maker.retone();
        }
        reloads.takePending();
        view.resized(input.viewWidth(), input.viewHeight());
        if (in.wheelNotches() != 0) {
            status.changed();
        }
        CameraController controller = view.controller();
        if (in.orbitStarted()) { // the point under the mouse, with the camera the user saw it from
            controller.orbitAround(OrbitPivot.pick(view.compiled(), controller.camera(), in, size.width(),
                    size.height()));
        }
        if (in.focusClicked()) { // the point under the mouse, with the camera the user saw it from
            String note = view.focusOn(OrbitPivot.under(view.compiled(), controller.camera(), in.focusX(),
                    in.focusY(), size.width(), size.height()));
            if (note != null) {
                status.note(note);
            }
        }
        boolean moved = view.fly(in);
        if (in.seconds(Action.ZOOM_IN) > 0 || in.seconds(Action.ZOOM_OUT) > 0) { // Z or X held: the fov as it changes
            status.note(controller.fovNote());
        }
        if (moved) {
            lastMotion = start;
        }
        for (Action command : in.commands()) {
            if (command.jumpsCamera()) { // after the interval's motion: the key came after it
                commands.run(command, in);
            }
        }
        int samples = Refinement.passes(view.settings().still());
        boolean moving = moved || in.motionHeld() || start - lastMotion < MOTION_HOLD_NANOS;
        boolean refining = view.passesDone() == 0 || view.passesDone() < samples && !maker.refinementDone();
        boolean frameDue = moving ? view.needFrame() : refining;
        if (frameDue && start < maker.retryAt()) { // the last try failed: the next one comes when the pause is over
            frames.presentIfChanged();
            return maker.retryAt() - start;
        }
        if (moving && view.needFrame()) {
            return maker.moving(start) ? 0 : maker.retryAt() - clock.nanoTime();
        }
        if (!moving && refining) {
            return maker.pass(start) ? 0 : maker.retryAt() - clock.nanoTime();
        }
        if (moving) { // nothing new to draw yet: wait for input, or for the end of the motion hold
            frames.presentIfChanged();
            return in.motionHeld() ? IDLE : lastMotion + MOTION_HOLD_NANOS - start;
        }
        frames.idle(); // the overlay says idle, or shows a new message
        return IDLE;
    }

    /** F5 read the config again: every part takes its settings. */
    private void configure(Config c) {
        view.configFile(c); // the view's settings, speeds and frame budget, drawn anew
        maker.configure(c);
        source.limits(c.limits().scene());
        presenter.title(c.name());
    }
}
