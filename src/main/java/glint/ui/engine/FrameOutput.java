package glint.ui.engine;

import glint.render.LightTransport;
import glint.ui.frames.FrameRenderer;
import glint.ui.frames.Refinement;
import glint.ui.scenes.SceneSource;
import glint.ui.screen.FrameStats;
import glint.ui.screen.Presenter;
import glint.ui.screen.ShownFrame;
import glint.ui.view.FrameSize;
import glint.ui.view.SceneView;
import glint.ui.view.StatusLine;
import glint.ui.view.ViewSettings;
import java.awt.image.BufferedImage;
import java.io.PrintWriter;
import java.util.Locale;

/**
 * Hands frames to the {@link Presenter} with the overlay's figures: a new image, or the last one again when
 * only the figures or messages changed. Engine thread only, except {@link #shown()}, which any thread may
 * read.
 */
final class FrameOutput {

    private final Presenter presenter;
    private final SceneView view;
    private final FrameSize size;
    private final StatusLine status;
    private final SceneSource source;
    private final FrameRenderer renderer;
    private final RenderFaults faults;
    private final PrintWriter err;
    private final FrameRateMeter meter = new FrameRateMeter();
    private BufferedImage lastImage;
    private FrameStats lastStats;
    private long serial;
    private volatile ShownFrame shownNow;

    FrameOutput(Presenter presenter, SceneView view, FrameSize size, StatusLine status, SceneSource source,
                FrameRenderer renderer, RenderFaults faults, PrintWriter err) {
        this.presenter = presenter;
        this.view = view;
        this.size = size;
        this.status = status;
        this.source = source;
        this.renderer = renderer;
        this.faults = faults;
        this.err = err;
    }

    /** Shows a new frame, finished at {@code end} after {@code nanos}, of {@code samples} samples a pixel. */
    void show(BufferedImage image, long end, long nanos, int samples, boolean moving) {
        meter.frame(end);
        lastImage = image;
        lastStats = stats(meter.fps(), nanos / 1e6, image.getWidth(), image.getHeight(), size.width(), size.height(),
                samples, moving);
        publish();
        if (view.settings().config().debug() && meter.windowClosed()) {
            err.println(String.format(Locale.ROOT, "glint: window %.1f fps, %.1f ms/frame, %dx%d of %dx%d, %s",
                    lastStats.fps(), lastStats.msPerFrame(), lastStats.renderWidth(), lastStats.renderHeight(),
                    size.width(), size.height(), moving ? "moving" : "still, samples " + samples + "/"
                            + view.settings().config().samples()));
        }
    }

    /** Shows {@code image} in place of the last one (the same frame encoded again), with the same figures. */
    void replace(BufferedImage image) {
        lastImage = image;
        presentStatus();
    }

    /** Shows the last image again with the current messages and settings. */
    void presentStatus() {
        FrameStats s = lastStats;
        lastStats = s == null
                ? stats(Double.NaN, 0, 0, 0, size.width(), size.height(), 0, false)
                : stats(meter.fps(), s.msPerFrame(), s.renderWidth(), s.renderHeight(), s.viewWidth(), s.viewHeight(),
                        s.samplesDone(), s.moving() && view.passesDone() == 0);
        publish();
    }

    /** Shows the last image again if the overlay is behind. */
    void presentIfChanged() {
        if (status.isChanged()) {
            presentStatus();
        }
    }

    /** Nothing more to render: the frame rate stops, and the overlay says idle (or shows a new message). */
    void idle() {
        boolean wasRendering = meter.isRunning();
        meter.pause();
        if (status.isChanged() || wasRendering) {
            presentStatus();
        }
    }

    /** The image on screen, or null before the first frame. */
    BufferedImage lastImage() {
        return lastImage;
    }

    /** The last frame handed to the presenter, or null (any thread). */
    ShownFrame shown() {
        return shownNow;
    }

    /** The overlay's figures for a frame of this size, with the engine's settings and messages now. */
    private FrameStats stats(double fps, double msPerFrame, int renderWidth, int renderHeight, int frameViewWidth,
                             int frameViewHeight, int samplesDone, boolean moving) {
        ViewSettings seen = view.settings();
        boolean path = seen.transport().physical();
        double noise = path && !moving && samplesDone > 1 ? renderer.relativeNoise() : Double.NaN;
        return new FrameStats(fps, msPerFrame, renderWidth, renderHeight, frameViewWidth, frameViewHeight,
                samplesDone, Refinement.passes(seen.still()), moving, renderer.threads(), seen.shading(),
                seen.transport(), noise, seen.depth(),
                view.controller().speed(), source.scenePath().toString(), status.message(), status.error(),
                size.sizeLimit(), faults.overlayLine(), view.camera().aperture() > 0 ? view.controller().lensNote() : "",
                seen.view().describe(), !moving && seen.transport().physical() && renderer.converged());
    }

    private void publish() {
        status.shown();
        ShownFrame frame = new ShownFrame(lastImage, lastStats, ++serial);
        shownNow = frame;
        presenter.present(frame);
    }
}
