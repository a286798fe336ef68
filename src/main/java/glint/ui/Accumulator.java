package glint.ui;

import glint.render.FrameBuffer;

/**
 * Progressive refinement while the camera is still: adds the sample passes of one view and keeps
 * their plain average, which after all passes is the still image (SPEC section 3). Adding a pass and
 * encoding the average to 8-bit sRGB are one loop over a range of pixels, so that the window can split
 * a pass among threads ({@link FrameRenderer}).
 */
final class Accumulator {

    private int width;
    private int height;
    private double[] sum;
    private int passes;
    private int weight = 1; // passes in the frame being added

    /** Starts over for a width x height view. */
    void reset(int newWidth, int newHeight) {
        if (sum == null || newWidth != width || newHeight != height) {
            sum = null; // the old one can go before the new one is taken
            sum = new double[3 * newWidth * newHeight];
            width = newWidth;
            height = newHeight;
        } else {
            java.util.Arrays.fill(sum, 0);
        }
        passes = 0;
    }

    /** Passes added since the last reset. */
    int passes() {
        return passes;
    }

    /** Counts one more pass; its pixels are then added by {@link #addAndEncode}, range by range. */
    void beginPass() {
        beginPasses(1);
    }

    /** Counts {@code count} more passes, traced in one go: their average is added with weight {@code count}. */
    void beginPasses(int count) {
        passes += count;
        weight = count;
    }

    /**
     * Adds pixels {@code from} (inclusive) to {@code to} (exclusive) of a pass to the sums and writes the
     * average so far, as dithered 8-bit sRGB, to {@code rgb} (0xRRGGBB a pixel). Ranges that do not overlap may be
     * done on different threads at once.
     */
    void addAndEncode(FrameBuffer pass, int[] rgb, int from, int to) {
        float[] in = pass.rgb();
        double[] s = sum;
        double inverse = 1.0 / passes;
        double w = weight;
        int width = pass.width();
        int x = from % width, y = from / width;
        for (int p = from, i = 3 * from; p < to; p++, i += 3) {
            double r = s[i] + w * in[i];
            double g = s[i + 1] + w * in[i + 1];
            double b = s[i + 2] + w * in[i + 2];
            s[i] = r;
            s[i + 1] = g;
            s[i + 2] = b;
            rgb[p] = SrgbEncoder.pixel((float) (r * inverse), (float) (g * inverse), (float) (b * inverse), x, y);
            if (++x == width) {
                x = 0;
                y++;
            }
        }
    }
}
