package glint.image;

/**
 * A width x height image of linear RGB radiance, rows top to bottom, 3 floats a pixel. Every value
 * stored is a finite float: what would not be one is stored as the nearest that is
 * ({@link #storable}), so no infinity or NaN ever reaches a PNG, a PFM or the window.
 */
public final class FrameBuffer {

    /** The largest radiance a frame stores: the largest finite float (about 3.4e38). */
    public static final double LARGEST = Float.MAX_VALUE;

    private final int width;
    private final int height;
    private final float[] rgb;

    public FrameBuffer(int width, int height) {
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("image size must be positive, got " + width + "x" + height);
        }
        this.width = width;
        this.height = height;
        this.rgb = new float[3 * width * height];
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** The backing array: pixel (x, y) channel c is at 3 (y width + x) + c. */
    public float[] rgb() {
        return rgb;
    }

    /** Stores pixel (x, y), each channel as {@link #storable} makes it. */
    public void set(int x, int y, double r, double g, double b) {
        int i = 3 * (y * width + x);
        rgb[i] = storable(r);
        rgb[i + 1] = storable(g);
        rgb[i + 2] = storable(b);
    }

    public float get(int x, int y, int channel) {
        return rgb[3 * (y * width + x) + channel];
    }

    /**
     * A radiance as the frame stores it: the float nearest to it when that is finite; beyond the
     * largest float (or infinite), the largest float of its sign; NaN, a value that has no meaning,
     * as 0.
     */
    public static float storable(double value) {
        if (Math.abs(value) <= LARGEST) {
            return (float) value;
        }
        return value > 0 ? Float.MAX_VALUE : value < 0 ? -Float.MAX_VALUE : 0f;
    }
}
