package glint.ui.capture;

import glint.scene.Camera;
import glint.ui.scenes.SceneSource;
import glint.ui.view.FrameSize;
import glint.ui.view.SceneView;
import java.awt.image.BufferedImage;
import java.io.PrintWriter;
import java.util.Optional;
import java.util.function.Supplier;

/**
 * Images of the view saved to files: the window's pixels (F12, {@link Screenshots}), and the view rendered
 * as a still in the background (Enter, {@link StillRender}), which this class starts, cancels and closes.
 * Engine thread only.
 */
public final class Captures implements AutoCloseable {

    private final Screenshots screenshots;
    private final StillRender stills;
    private final SceneView view;
    private final FrameSize size;
    private final SceneSource source;
    private final Supplier<BufferedImage> lastImage;
    private final PrintWriter err;

    /**
     * @param stills    renders the stills (this class closes it)
     * @param lastImage the image on screen, or null before the first frame
     */
    public Captures(Screenshots screenshots, StillRender stills, SceneView view, FrameSize size, SceneSource source,
             Supplier<BufferedImage> lastImage, PrintWriter err) {
        this.screenshots = screenshots;
        this.stills = stills;
        this.view = view;
        this.size = size;
        this.source = source;
        this.lastImage = lastImage;
        this.err = err;
    }

    /** F12: saves the image on screen; returns what the overlay says. */
    public String screenshot() {
        BufferedImage image = lastImage.get();
        if (image == null) {
            return "nothing to save yet";
        }
        // the window's size, or at most the frame size budget (a huge window: the largest frame allowed)
        return screenshots.saveView(image, size.fit(1), size.sizeLimit(), err);
    }

    /**
     * The render key: starts a still of the view at the still's settings (with a PFM beside the PNG if
     * {@code pfm}), or cancels the one under way; returns what the overlay says. The still's report goes to
     * {@code out}.
     */
    public String still(boolean pfm, PrintWriter out) {
        if (stills.running()) {
            return stills.cancel();
        }
        String refusal = view.stillRefusal();
        if (refusal.isEmpty()) { // saved since, loading, not on screen yet: the command would read the new file
            refusal = source.changedSince(view.scene());
        }
        if (!refusal.isEmpty()) { // its headless command would not give the image on screen
            return "still not rendered: the headless command would not give this view: " + refusal;
        }
        Camera printed = CameraBlock.asPrinted(view.controller().camera()); // the camera a pasted block gives
        return stills.start(StillRender.job(view.compiled().withCamera(printed), printed,
                view.settings().still(view.scene(), size.fit(1)), source.scenePath(), source.configFile(), screenshots,
                pfm), out, err);
    }

    /** Whether a still is being rendered. */
    public boolean stillRunning() {
        return stills.running();
    }

    /** Cancels the still under way; returns what the overlay says. */
    public String cancelStill() {
        return stills.cancel();
    }

    /** What the still under way, or the one just ended, has to say since the last call. */
    public Optional<String> stillNews() {
        return stills.news();
    }

    /**
     * Cancels a still under way and waits (a bounded time) until its hidden files are deleted; returns
     * whether a still under way was cancelled.
     */
    public boolean stop() {
        return stills.stop();
    }

    /**
     * Cancels a still under way at once, its hidden files deleted, without waiting for its thread (any thread);
     * returns whether one was under way.
     */
    public boolean cancelNow() {
        return stills.cancelNow();
    }

    @Override
    public void close() {
        stop();
    }
}
