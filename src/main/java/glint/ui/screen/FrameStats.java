package glint.ui.screen;

import glint.render.LightTransport;
import glint.render.Shading;

/**
 * What the overlay shows about the frame on screen and the engine's state.
 *
 * @param fps           frames per second while frames are being rendered back to back; NaN when idle
 * @param msPerFrame    how long the last frame took, from input to shown
 * @param renderWidth   the frame's size in pixels
 * @param renderHeight  the frame's size in pixels
 * @param viewWidth     the window's drawing area in pixels
 * @param viewHeight    the window's drawing area in pixels
 * @param samplesDone   samples per pixel accumulated in the frame
 * @param samplesTotal  the configured samples per pixel
 * @param moving        whether the camera is moving (adaptive resolution, no refinement)
 * @param threads       render threads
 * @param shading       shading model
 * @param transport     the integrator
 * @param noise         the noise left in a path frame at rest, relative to its brightness; NaN when not known
 * @param depth         recursion depth (recursion_max)
 * @param speed         flying speed in scene units per second, without Shift
 * @param scene         the scene file
 * @param message       the last thing done (screenshot saved, depth changed, ...), or empty
 * @param error         the last load or save error, {@code file:line:col: message}, or empty
 * @param sizeLimit     why the render size is smaller than the window's ({@code max_image_pixels ...}), or
 *                      empty when the window is within the limits
 * @param renderError   why the last frame could not be rendered (the engine tries again), or empty
 * @param lens          the camera's lens, {@code aperture 0.1  focus 5.3}, or empty for a pinhole
 * @param view          the view transform, {@code exposure +1  tone neutral}, or empty when not shown
 * @param converged     whether every pixel of a path or bdpt frame at rest has converged (adaptive sampling), so
 *                      nothing more is traced
 */
public record FrameStats(double fps, double msPerFrame, int renderWidth, int renderHeight, int viewWidth,
                         int viewHeight, int samplesDone, int samplesTotal, boolean moving, int threads,
                         Shading shading, LightTransport transport, double noise, int depth, double speed,
                         String scene, String message, String error, String sizeLimit, String renderError,
                         String lens, String view, boolean converged) {

    /** Figures of a frame whose refinement has not converged. */
    public FrameStats(double fps, double msPerFrame, int renderWidth, int renderHeight, int viewWidth,
                      int viewHeight, int samplesDone, int samplesTotal, boolean moving, int threads,
                      Shading shading, LightTransport transport, double noise, int depth, double speed,
                      String scene, String message, String error, String sizeLimit, String renderError,
                      String lens, String view) {
        this(fps, msPerFrame, renderWidth, renderHeight, viewWidth, viewHeight, samplesDone, samplesTotal, moving,
                threads, shading, transport, noise, depth, speed, scene, message, error, sizeLimit, renderError, lens,
                view, false);
    }

    /** Figures without the view transform's line. */
    public FrameStats(double fps, double msPerFrame, int renderWidth, int renderHeight, int viewWidth,
                      int viewHeight, int samplesDone, int samplesTotal, boolean moving, int threads,
                      Shading shading, LightTransport transport, double noise, int depth, double speed,
                      String scene, String message, String error, String sizeLimit, String renderError,
                      String lens) {
        this(fps, msPerFrame, renderWidth, renderHeight, viewWidth, viewHeight, samplesDone, samplesTotal, moving,
                threads, shading, transport, noise, depth, speed, scene, message, error, sizeLimit, renderError, lens,
                "");
    }

    /** Figures of a Whitted frame through a pinhole, whose noise is not estimated. */
    public FrameStats(double fps, double msPerFrame, int renderWidth, int renderHeight, int viewWidth,
                      int viewHeight, int samplesDone, int samplesTotal, boolean moving, int threads,
                      Shading shading, int depth, double speed, String scene, String message, String error,
                      String sizeLimit, String renderError) {
        this(fps, msPerFrame, renderWidth, renderHeight, viewWidth, viewHeight, samplesDone, samplesTotal, moving,
                threads, shading, LightTransport.WHITTED, Double.NaN, depth, speed, scene, message, error, sizeLimit,
                renderError, "");
    }

    /** Whether the image is final: still, and every sample accumulated or every pixel converged. */
    public boolean refined() {
        return !moving && (samplesDone >= samplesTotal || converged);
    }
}
