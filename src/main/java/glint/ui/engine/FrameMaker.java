package glint.ui.engine;

import glint.config.Config;
import glint.ui.frames.FrameRenderer;
import glint.ui.frames.RefinePacing;
import glint.ui.frames.Refinement;
import glint.ui.frames.ResolutionGovernor;
import glint.ui.input.Clock;
import glint.ui.view.FrameSize;
import glint.ui.view.SceneView;
import glint.ui.view.StatusLine;
import java.awt.image.BufferedImage;
import java.io.PrintWriter;

/**
 * Makes the window's frames and shows them: a moving frame at the size the {@link ResolutionGovernor}
 * allows, or the next still passes at full size ({@link RefinePacing}). A frame that fails to render keeps
 * the last good one on screen, says why in the overlay and once on standard error, and is tried again after
 * {@link RenderFaults#RETRY_NANOS} ({@link RenderFaults}). Engine thread only.
 */
final class FrameMaker implements AutoCloseable {

    private final FrameRenderer renderer;
    private final ResolutionGovernor governor;
    private final RenderFaults faults;
    private final RefinePacing pacing = new RefinePacing();
    private final SceneView view;
    private final FrameSize size;
    private final FrameOutput frames;
    private final StatusLine status;
    private final Clock clock;
    private final PrintWriter err;

    FrameMaker(FrameRenderer renderer, ResolutionGovernor governor, RenderFaults faults, SceneView view,
               FrameSize size, FrameOutput frames, StatusLine status, Clock clock, PrintWriter err) {
        this.renderer = renderer;
        this.governor = governor;
        this.faults = faults;
        this.view = view;
        this.size = size;
        this.frames = frames;
        this.status = status;
        this.clock = clock;
        this.err = err;
    }

    /** Renders and shows a moving frame; false if it failed (shown, and tried again later). */
    boolean moving(long start) {
        ResolutionGovernor.Size s = size.fit(governor.scale());
        BufferedImage image;
        renderer.viewTransform(view.settings().view());
        try {
            image = renderer.renderMoving(view.compiled(), s.width(), s.height());
        } catch (RuntimeException | OutOfMemoryError e) {
            failed(e);
            frames.presentStatus();
            return false;
        }
        view.movingFrameShown();
        long end = clock.nanoTime();
        governor.frameTook((end - start) / 1e9);
        rendered();
        frames.show(image, end, end - start, 1, true);
        return true;
    }

    /** Renders and shows the next still passes; false if it failed (shown, and tried again later). */
    boolean pass(long start) {
        ResolutionGovernor.Size s = size.fit(1);
        Config config = view.settings().still();
        int samples = Refinement.passes(config), pattern = Refinement.pattern(config);
        int done = view.passesDone();
        int count = renderer.inOneCall(Refinement.inOneCall(pacing.passes(done, samples, start), done, pattern), done);
        BufferedImage image;
        renderer.viewTransform(view.settings().view());
        try {
            image = renderer.renderPasses(view.compiled(), s.width(), s.height(), pattern, done, count,
                    Refinement.threshold(config), samples);
        } catch (RuntimeException | OutOfMemoryError e) {
            failed(e);
            frames.presentStatus();
            return false;
        }
        view.passesShown(count);
        long end = clock.nanoTime();
        rendered();
        pacing.passesDone(view.passesDone(), count, samples, start, end, s, config.debug() ? err : null);
        frames.show(image, end, end - start, view.passesDone(), false);
        return true;
    }

    /**
     * The exposure or the tone changed: the frame on screen is encoded again through the view transform now and
     * shown, nothing traced (the refinement goes on from where it was). Nothing happens before the first frame.
     */
    void retone() {
        renderer.viewTransform(view.settings().view());
        BufferedImage image = renderer.again();
        if (image != null) {
            frames.replace(image);
        }
    }

    /**
     * A frame could not be made. The last good frame stays on screen; the overlay says why; standard error
     * says so once, not once a frame; the frame is tried again after {@link RenderFaults#RETRY_NANOS}, input
     * or not.
     */
    void failed(Throwable e) {
        String line = faults.failed(e, clock.nanoTime());
        if (line != null) {
            err.println(line);
        }
        view.frameFailed();
        status.changed();
    }

    /** When the next try is due after a failure (in the past once it is due). */
    long retryAt() {
        return faults.retryAt();
    }

    /**
     * Whether the still refinement on screen has nothing left to trace (every pixel converged, or the cap
     * reached), so the engine waits, tracing nothing.
     */
    boolean refinementDone() {
        return renderer.refinementDone();
    }

    /** Traces about {@code nanos} of still passes in one go while passes are quicker ({@link RefinePacing}). */
    void paceRefinement(long nanos) {
        pacing.interval(nanos);
    }

    /** The config's frame rate, scale, threads and tiles from now on. */
    void configure(Config c) {
        governor.setLimits(c.targetFps(), c.displayScale());
        renderer.configure(c.effectiveThreads(), c.screenDivider());
    }

    /** Frees the render threads. */
    @Override
    public void close() {
        renderer.close();
    }

    /** A frame was made: a run of failures, if any, is over. */
    private void rendered() {
        String line = faults.rendered();
        if (line != null) {
            err.println(line);
            status.note("rendering works again");
        }
    }
}
