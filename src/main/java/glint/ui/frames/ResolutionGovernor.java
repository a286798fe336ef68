package glint.ui.frames;

/**
 * Chooses the render scale s while the camera moves: frames are rendered at (width / s) x
 * (height / s) and scaled up to the window. Render time grows with the pixel count, 1 / s^2, so after
 * each frame s moves towards s x sqrt(frame time / target time), damped against noise, and is kept
 * within [1, display_scale]: the resolution drops only as far as needed to hold the target frame
 * rate, and never below 1 / display_scale of the window (the seed's display_scale is the floor).
 */
public final class ResolutionGovernor {

    /** Fraction of the correction applied per frame (1 = jump at once; smaller is steadier). */
    static final double GAIN = 0.7;
    /** Relative changes smaller than this are ignored, so that the image does not shimmer. */
    static final double DEAD_BAND = 0.04;

    private double targetSeconds;
    private double maxScale;
    private double scale;

    public ResolutionGovernor(double targetFps, double maxScale) {
        setLimits(targetFps, maxScale);
        this.scale = this.maxScale;
    }

    /** New target and floor (after a config reload); the scale stays within them. */
    public void setLimits(double targetFps, double newMaxScale) {
        this.targetSeconds = 1 / targetFps;
        this.maxScale = Math.max(1, newMaxScale);
        this.scale = Math.max(1, Math.min(this.maxScale, scale == 0 ? this.maxScale : scale));
    }

    /** The scale for the next moving frame, from 1 to display_scale. */
    public double scale() {
        return scale;
    }

    /** Records how long a moving frame rendered at {@link #scale()} took, start to shown. */
    public void frameTook(double seconds) {
        if (!(seconds > 0)) {
            return;
        }
        double wanted = scale * Math.pow(seconds / targetSeconds, 0.5 * GAIN);
        wanted = Math.max(1, Math.min(maxScale, wanted));
        if (Math.abs(wanted / scale - 1) > DEAD_BAND || wanted == 1 || wanted == maxScale) {
            scale = wanted;
        }
    }

    /** The render size of a window side of {@code viewPixels} at scale {@code s}. */
    public static int renderSize(int viewPixels, double s) {
        return Math.max(1, (int) Math.round(viewPixels / s));
    }

    /** A render size in pixels. */
    public record Size(int width, int height) {

        public long pixels() {
            return (long) width * height;
        }
    }

    /**
     * The render size of a viewWidth x viewHeight view at scale {@code s}, made smaller still (same
     * aspect) where it would have more than {@code maxPixels} pixels: a huge window never makes a huge
     * frame buffer.
     */
    public static Size renderSize(int viewWidth, int viewHeight, double s, long maxPixels) {
        double scale = Math.max(s, Math.sqrt((double) viewWidth * viewHeight / Math.max(1, maxPixels)));
        Size size = new Size(renderSize(viewWidth, scale), renderSize(viewHeight, scale));
        while (size.pixels() > maxPixels && size.pixels() > 1) { // rounding up took it just over
            scale *= 1.001;
            size = new Size(renderSize(viewWidth, scale), renderSize(viewHeight, scale));
        }
        return size;
    }
}
