package glint.ui.view;

import glint.config.Limits;
import glint.ui.frames.ResolutionGovernor;
import java.util.Locale;

/**
 * The most pixels a window frame may have, whatever the window's size: the config's
 * {@code max_image_pixels}, and no more than half the Java heap can hold. A larger window is rendered
 * at the largest size allowed (same aspect) and scaled up.
 *
 * @param pixels the budget, at least 1
 * @param why    what sets it, for the overlay: {@code 10,000 pixels (max_image_pixels)}
 */
record FrameBudget(long pixels, String why) {

    /**
     * Heap bytes per rendered pixel: the float frame buffer (12), the refinement's sums, counts and noise
     * statistics ({@link glint.render.Convergence#BYTES_PER_PIXEL}, 54), the image on screen, the one being made
     * and a screenshot's (3 x 4): 78, rounded up.
     */
    static final long BYTES_PER_PIXEL = 80;

    /** The budget under these limits with this much heap at most ({@link Runtime#maxMemory}). */
    static FrameBudget of(Limits limits, long maxHeapBytes) {
        long pixels = Math.max(1, Math.min(limits.maxImagePixels(), maxHeapBytes / 2 / BYTES_PER_PIXEL));
        return new FrameBudget(pixels, String.format(Locale.ROOT, "%,d pixels (%s)", pixels,
                pixels == limits.maxImagePixels() ? "max_image_pixels" : "half the Java heap, -Xmx"));
    }

    /** True when a viewWidth x viewHeight frame would be over the budget. */
    boolean binds(int viewWidth, int viewHeight) {
        return (long) viewWidth * viewHeight > pixels;
    }

    /** The render size of the view at scale {@code s}, within the budget. */
    ResolutionGovernor.Size fit(int viewWidth, int viewHeight, double s) {
        return ResolutionGovernor.renderSize(viewWidth, viewHeight, s, pixels);
    }
}
