package glint.render;

/** A width x height image of linear RGB radiance, rows top to bottom, 3 floats a pixel. */
public final class FrameBuffer {

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

    public void set(int x, int y, double r, double g, double b) {
        int i = 3 * (y * width + x);
        rgb[i] = (float) r;
        rgb[i + 1] = (float) g;
        rgb[i + 2] = (float) b;
    }

    public float get(int x, int y, int channel) {
        return rgb[3 * (y * width + x) + channel];
    }
}
