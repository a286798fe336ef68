package glint.ui;

import glint.config.Config;
import glint.input.InputException;
import glint.render.RenderScene;
import glint.scene.Camera;
import glint.scene.Scene;
import glint.scene.View;
import java.awt.image.BufferedImage;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;

/**
 * The window's loop, on its own thread: input, camera update, render, present. While the camera
 * moves it renders one-sample frames at the resolution the {@link ResolutionGovernor} allows; when it
 * is still it renders the full resolution in sample passes that accumulate up to the configured
 * samples, then waits without using the CPU until something changes.
 *
 * <p>{@link #step} is one turn of the loop and is what tests drive with their own clock; {@link #run}
 * repeats it and waits on {@link InputState#awaitActivity} as long as it asks.
 *
 * <p>Faults do not end it: a frame that fails to render (a render worker threw, memory ran out) keeps the
 * last good frame on screen, shows why in the overlay, says so once on standard error, and is tried again
 * after {@link RenderFaults#RETRY_NANOS} without waiting for input. A window larger than the config's
 * {@code max_image_pixels} (or than half the heap can hold) is rendered smaller and scaled up.
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
    private final Screenshots screenshots;
    private final Clock clock;
    private final PrintWriter err;
    private PrintWriter out = new PrintWriter(System.out, true); // key C's camera block
    private final CameraController controller;
    private final ResolutionGovernor governor;
    private final FrameRenderer renderer;
    private final StillRender stills;
    private final RefinePacing pacing = new RefinePacing();
    private final FrameRateMeter meter = new FrameRateMeter();
    private final AtomicReference<Object> pendingScene = new AtomicReference<>(); // Scene or InputException
    private final CountDownLatch finished = new CountDownLatch(1);

    private final ViewSettings seen; // the scene's settings, the user's shading and depth
    private Scene scene;
    private Camera fileCamera;

    private int viewWidth;
    private int viewHeight;
    private final CompiledScenes compiledScenes = new CompiledScenes();
    private RenderScene compiled; // null: compile again before the next frame
    private boolean needFrame = true;
    private int passesDone;
    private long lastMotion;
    private BufferedImage lastImage;
    private FrameStats lastStats;
    private long serial;
    private String message = "";
    private String error = "";
    private boolean statusChanged;
    private FrameBudget budget;
    private String sizeLimit = ""; // why frames are smaller than the window, or empty
    private final RenderFaults faults = new RenderFaults();

    private volatile boolean running = true;
    private volatile boolean failed;
    private volatile Camera cameraNow;
    private volatile Scene sceneNow;
    private volatile String errorNow = "";
    private volatile ShownFrame shownNow;

    public Engine(Config config, Scene scene, SceneSource source, InputState input, Presenter presenter,
                  Screenshots screenshots, Clock clock, PrintWriter err) {
        this(config, scene, source, input, presenter, screenshots, clock, err, FrameRenderer.TraceCall.TRACER);
    }

    /** An engine whose frames are traced by {@code trace} (tests: injected faults, stamped frames). */
    Engine(Config config, Scene scene, SceneSource source, InputState input, Presenter presenter,
           Screenshots screenshots, Clock clock, PrintWriter err, FrameRenderer.TraceCall trace) {
        this.seen = new ViewSettings(config, source.flags());
        this.source = source;
        this.input = input;
        this.presenter = presenter;
        this.screenshots = screenshots;
        this.clock = clock;
        this.err = err;
        this.controller = new CameraController(scene.camera(), config.moveSpeed(), config.turnSpeed());
        controller.setFreeFlight(config.freeFlight());
        this.governor = new ResolutionGovernor(config.targetFps(), config.displayScale());
        this.renderer = new FrameRenderer(config.effectiveThreads(), config.screenDivider(), trace);
        this.stills = new StillRender(input::signal);
        this.viewWidth = input.viewWidth();
        this.viewHeight = input.viewHeight();
        this.lastMotion = clock.nanoTime() - MOTION_HOLD_NANOS - 1;
        source.limits(config.limits().scene());
        checkSize();
        setScene(scene, true);
    }

    // ---- what other threads may ask or tell ----

    /** The camera now (any thread). */
    public Camera camera() {
        return cameraNow;
    }

    /** The scene on screen: the last one that loaded (any thread). */
    public Scene scene() {
        return sceneNow;
    }

    /** The last load error as {@code file:line:col: message}, or empty (any thread). */
    public String error() {
        return errorNow;
    }

    /** The last frame handed to the presenter, or null (any thread). */
    public ShownFrame shown() {
        return shownNow;
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
        input.signal();
    }

    /** Where key C prints the camera block (standard output unless a test says otherwise). */
    void printTo(PrintWriter printer) {
        this.out = printer;
    }

    /** Traces about {@code nanos} of still passes in one go while passes are quicker ({@link RefinePacing}). */
    void paceRefinement(long nanos) {
        pacing.interval(nanos);
    }

    /** Waits until {@link #run} has returned. */
    public boolean awaitFinished(long timeout, TimeUnit unit) throws InterruptedException {
        return finished.await(timeout, unit);
    }

    /** Frees the render threads when the loop was driven by {@link #step} alone (tests). */
    public void close() {
        stills.close();
        renderer.close();
    }

    @Override
    public void loaded(Scene newScene) {
        pendingScene.set(newScene);
        input.signal();
    }

    @Override
    public void failed(InputException problem) {
        pendingScene.set(problem);
        input.signal();
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
                    frameFailed(e); // shown and logged once; the frame is tried again
                    wait = RETRY_NANOS;
                }
                if (running && wait > 0) {
                    input.awaitActivity(wait);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (Error e) {
            failed = true;
            err.println("glint: the window's engine stopped: " + e);
        } finally {
            running = false;
            stills.close(); // a still under way is cancelled, and its hidden file deleted, before the end
            renderer.close();
            finished.countDown();
        }
    }

    /**
     * One turn of the loop; returns how long to wait for input before the next one (0: go on at
     * once, {@link #IDLE}: until something happens).
     */
    public long step() {
        stills.news().ifPresent(this::note); // a still's progress, or its end
        long wait = stepOnce();
        return stills.running() ? Math.min(wait, StillRender.POLL_NANOS) : wait; // its progress is shown
    }

    private long stepOnce() {
        long start = clock.nanoTime();
        InputFrame in = input.drain();
        for (Action command : in.commands()) {
            if (!command.jumpsCamera()) {
                command(command, in);
            }
        }
        if (!running) {
            return 0;
        }
        takePendingScene();
        if (input.viewWidth() != viewWidth || input.viewHeight() != viewHeight) {
            viewWidth = input.viewWidth();
            viewHeight = input.viewHeight();
            checkSize();
            invalidate();
        }
        if (in.wheelNotches() != 0) {
            statusChanged = true;
        }
        if (in.orbitStarted()) { // the point under the mouse, with the camera the user saw it from
            controller.orbitAround(OrbitPivot.pick(compiled(), controller.camera(), in, viewWidth, viewHeight));
        }
        boolean moved = controller.apply(in);
        if (moved) {
            lastMotion = start;
            cameraNow = controller.camera();
            invalidate();
        }
        for (Action command : in.commands()) {
            if (command.jumpsCamera()) { // after the interval's motion: the key came after it
                command(command, in);
            }
        }
        boolean moving = moved || in.motionHeld() || start - lastMotion < MOTION_HOLD_NANOS;
        boolean frameDue = moving ? needFrame : passesDone < seen.config.samples();
        if (frameDue && start < faults.retryAt()) { // the last try failed: the next one comes when the pause is over
            if (statusChanged) {
                presentStatus();
            }
            return faults.retryAt() - start;
        }
        if (moving && needFrame) {
            return renderMoving(start) ? 0 : faults.retryAt() - clock.nanoTime();
        }
        if (!moving && passesDone < seen.config.samples()) {
            return renderPass(start) ? 0 : faults.retryAt() - clock.nanoTime();
        }
        if (moving) { // nothing new to draw yet: wait for input, or for the end of the motion hold
            if (statusChanged) {
                presentStatus();
            }
            return in.motionHeld() ? IDLE : lastMotion + MOTION_HOLD_NANOS - start;
        }
        boolean wasRendering = meter.isRunning();
        meter.pause();
        if (statusChanged || wasRendering) {
            presentStatus(); // the overlay says idle, or shows a new message
        }
        return IDLE;
    }

    /** Renders and shows a moving frame; false if it failed (shown, and tried again later). */
    private boolean renderMoving(long start) {
        ResolutionGovernor.Size size = budget.fit(viewWidth, viewHeight, governor.scale());
        BufferedImage image;
        try {
            image = renderer.renderMoving(compiled(), size.width(), size.height());
        } catch (RuntimeException | OutOfMemoryError e) {
            frameFailed(e);
            presentStatus();
            return false;
        }
        needFrame = false;
        passesDone = 0;
        long end = clock.nanoTime();
        governor.frameTook((end - start) / 1e9);
        rendered();
        show(image, end, end - start, 1, true);
        return true;
    }

    /** Renders and shows the next still pass; false if it failed (shown, and tried again later). */
    private boolean renderPass(long start) {
        ResolutionGovernor.Size size = budget.fit(viewWidth, viewHeight, 1);
        int samples = seen.config.samples();
        int count = pacing.passes(passesDone, samples, start); // quick passes: several in one go
        BufferedImage image;
        try {
            image = renderer.renderPasses(compiled(), size.width(), size.height(), samples, passesDone, count);
        } catch (RuntimeException | OutOfMemoryError e) {
            frameFailed(e);
            presentStatus();
            return false;
        }
        needFrame = false;
        passesDone += count;
        long end = clock.nanoTime();
        rendered();
        pacing.passesDone(passesDone, count, samples, start, end, size, seen.config.debug() ? err : null);
        show(image, end, end - start, passesDone, false);
        return true;
    }

    private void show(BufferedImage image, long end, long nanos, int samples, boolean moving) {
        meter.frame(end);
        lastImage = image;
        lastStats = stats(meter.fps(), nanos / 1e6, image.getWidth(), image.getHeight(), viewWidth, viewHeight,
                samples, moving);
        publish();
        if (seen.config.debug() && meter.windowClosed()) {
            err.println(String.format(Locale.ROOT, "glint: window %.1f fps, %.1f ms/frame, %dx%d of %dx%d, %s",
                    lastStats.fps(), lastStats.msPerFrame(), lastStats.renderWidth(), lastStats.renderHeight(),
                    viewWidth, viewHeight, moving ? "moving" : "still, samples " + samples + "/"
                            + seen.config.samples()));
        }
    }

    /** Shows the last image again with the current messages and settings. */
    private void presentStatus() {
        FrameStats s = lastStats;
        lastStats = s == null
                ? stats(Double.NaN, 0, 0, 0, viewWidth, viewHeight, 0, false)
                : stats(meter.fps(), s.msPerFrame(), s.renderWidth(), s.renderHeight(), s.viewWidth(), s.viewHeight(),
                        s.samplesDone(), s.moving() && passesDone == 0);
        publish();
    }

    /** The overlay's figures for a frame of this size, with the engine's settings and messages now. */
    private FrameStats stats(double fps, double msPerFrame, int renderWidth, int renderHeight, int frameViewWidth,
                             int frameViewHeight, int samplesDone, boolean moving) {
        return new FrameStats(fps, msPerFrame, renderWidth, renderHeight, frameViewWidth, frameViewHeight,
                samplesDone, seen.config.samples(), moving, renderer.threads(), seen.shading, seen.depth,
                controller.speed(),
                source.scenePath().toString(), message, error, sizeLimit, faults.overlayLine());
    }

    private void publish() {
        statusChanged = false;
        ShownFrame frame = new ShownFrame(lastImage, lastStats, ++serial);
        shownNow = frame;
        presenter.present(frame);
    }

    /**
     * A frame could not be made. The last good frame stays on screen; the overlay says why; standard error
     * says so once, not once a frame; the frame is tried again after {@link #RETRY_NANOS}, input or not.
     */
    private void frameFailed(Throwable e) {
        String line = faults.failed(e, clock.nanoTime());
        if (line != null) {
            err.println(line);
        }
        needFrame = true;
        passesDone = 0; // a failed pass may have reached the average: the refinement starts over
        statusChanged = true;
    }

    /** A frame was made: a run of failures, if any, is over. */
    private void rendered() {
        String line = faults.rendered();
        if (line != null) {
            err.println(line);
            note("rendering works again");
        }
    }

    /** The frame size budget for the window's size now; says once when it starts to bind. */
    private void checkSize() {
        budget = FrameBudget.of(seen.config.limits(), Runtime.getRuntime().maxMemory());
        boolean over = budget.binds(viewWidth, viewHeight);
        if (over && sizeLimit.isEmpty()) {
            ResolutionGovernor.Size size = budget.fit(viewWidth, viewHeight, 1);
            String line = String.format(Locale.ROOT, "the window is %dx%d; frames are rendered at %dx%d, at most %s",
                    viewWidth, viewHeight, size.width(), size.height(), budget.why());
            err.println("glint: " + line);
            note(line);
        }
        sizeLimit = over ? budget.why() : "";
    }

    // ---- what changes the view ----

    private RenderScene compiled() {
        if (compiled == null) {
            compiled = compiledScenes.of(scene, seen.render(), controller.camera());
        }
        return compiled;
    }

    private void invalidate() {
        compiled = null;
        needFrame = true;
        passesDone = 0;
        statusChanged = true;
    }

    private void command(Action action, InputFrame in) {
        switch (action) {
            case TOGGLE_SHADING -> {
                seen.shading = seen.shading.other();
                note("shading " + seen.shading.key());
                invalidate();
            }
            case DEPTH_UP, DEPTH_DOWN -> {
                int max = seen.config.limits().maxRecursion();
                int next = Math.max(1, Math.min(max, seen.depth + (action == Action.DEPTH_UP ? 1 : -1)));
                note(next == seen.depth ? "depth stays " + seen.depth + " (from 1 to " + max + ", max_recursion)"
                        : "depth " + next);
                if (next != seen.depth) {
                    seen.depth = next;
                    invalidate();
                }
            }
            case SCREENSHOT -> screenshot();
            case RELOAD -> reload();
            case LEVEL -> {
                if (controller.level()) {
                    cameraMoved();
                }
                note("level");
            }
            case HOME -> {
                controller.reset(fileCamera);
                cameraMoved();
                note("the scene's camera");
            }
            case VIEW -> view(in.view());
            case PRINT_CAMERA -> {
                note(CameraBlock.print(controller.camera(), out));
            }
            case NEXT_SCENE -> openNeighbour(1);
            case PREVIOUS_SCENE -> openNeighbour(-1);
            case RENDER_STILL, RENDER_STILL_PFM -> note(stills.running() ? stills.cancel()
                    : startStill(action == Action.RENDER_STILL_PFM));
            case QUIT -> {
                if (stills.running()) { // Esc stops the still first; the next one quits
                    note(stills.cancel());
                } else {
                    running = false;
                }
            }
            default -> {
                // overlay and help are the display's
            }
        }
    }

    /** The camera jumped (Home, a view, L): the view is drawn anew. */
    private void cameraMoved() {
        cameraNow = controller.camera();
        invalidate();
    }

    /** Keys 1 to 9: the scene's views. */
    private void view(int index) {
        List<View> views = scene.views();
        if (index < 0 || index >= views.size()) {
            note(views.isEmpty() ? "the scene has no views (views: in the scene file)"
                    : "the scene has " + views.size() + (views.size() == 1 ? " view (key 1)"
                    : " views (keys 1 to " + views.size() + ")"));
            return;
        }
        controller.reset(views.get(index).camera());
        cameraMoved();
        note("view " + (index + 1) + ": " + views.get(index).name());
    }

    /**
     * Page Down (+1) and Page Up (-1): the next or previous scene file (.yaml, .yml) of the current scene's
     * folder, by name, round to the first or last. The window watches that file from now on; one that does
     * not load says why and leaves the view as it was.
     */
    private void openNeighbour(int step) {
        SceneFolder.Neighbour found = SceneFolder.neighbour(source.scenePath(), step);
        if (found.path() == null) {
            note(found.problem());
            return;
        }
        Path target = found.path();
        source.scenePath(target);
        pendingScene.set(null); // a change the watcher saw in the old file is no longer wanted
        try {
            setScene(source.loadScene(), true);
            note("opened " + target + " (" + found.number() + " of " + found.of() + ")");
        } catch (InputException e) {
            setError(e.getMessage());
            note("opened " + target + ": it does not load");
        }
    }

    private void screenshot() {
        if (lastImage == null) {
            note("nothing to save yet");
            return;
        }
        // the window's size, or at most the frame size budget (a huge window: the largest frame allowed)
        note(screenshots.saveView(lastImage, budget.fit(viewWidth, viewHeight, 1), sizeLimit, err));
    }

    /** The render key: the view as a still at the still's settings, in the background. */
    private String startStill(boolean pfm) {
        Camera printed = CameraBlock.asPrinted(controller.camera()); // the camera a pasted block gives
        return stills.startOrCancel(StillRender.job(compiled().withCamera(printed), printed,
                seen.still(scene, budget.fit(viewWidth, viewHeight, 1)), source.scenePath(), screenshots, pfm), out, err);
    }

    /** F5: the config and the scene again; the camera goes back to the scene's. */
    private void reload() {
        String problem = "";
        try {
            applyConfig(source.loadConfig());
        } catch (InputException e) {
            problem = e.getMessage();
        }
        try {
            setScene(source.loadScene(), true);
        } catch (InputException e) {
            problem = problem.isEmpty() ? e.getMessage() : problem;
        }
        if (!problem.isEmpty()) { // else the scene's, which may be a render: block beyond the limits
            setError(problem);
        }
        note(problem.isEmpty() ? "reloaded " + source.scenePath() : "reload failed");
    }

    private void applyConfig(Config c) {
        seen.configFile(c, scene);
        controller.setSpeeds(c.moveSpeed(), c.turnSpeed());
        controller.setFreeFlight(c.freeFlight());
        governor.setLimits(c.targetFps(), c.displayScale());
        renderer.configure(c.effectiveThreads(), c.screenDivider());
        source.limits(c.limits().scene());
        checkSize();
        presenter.title(c.name());
        invalidate();
    }

    private void takePendingScene() {
        Object pending = pendingScene.getAndSet(null);
        if (pending instanceof Scene loadedScene) {
            setScene(loadedScene, false);
            note("reloaded " + source.scenePath());
        } else if (pending instanceof InputException problem) {
            setError(problem.getMessage());
        }
    }

    /**
     * Shows a new scene. The camera takes the file's pose when asked or when the file's camera
     * changed; otherwise the user's view stays where it is.
     */
    private void setScene(Scene newScene, boolean resetCamera) {
        if (resetCamera || !newScene.camera().equals(fileCamera)) {
            controller.reset(newScene.camera());
        }
        fileCamera = newScene.camera();
        seen.scene(newScene);
        setError(seen.blockError());
        scene = newScene;
        sceneNow = newScene;
        cameraNow = controller.camera();
        invalidate();
    }

    private void setError(String problem) {
        if (!problem.isEmpty() && !problem.equals(error)) {
            err.println(problem);
        }
        error = problem;
        errorNow = problem;
        statusChanged = true;
    }

    private void note(String text) {
        message = text;
        statusChanged = true;
    }

}
