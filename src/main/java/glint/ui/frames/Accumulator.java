package glint.ui.frames;

import glint.image.FrameBuffer;
import glint.image.ViewTransform;

/**
 * Progressive refinement while the camera is still: adds the sample passes of one view and keeps their
 * plain average, which after all passes is the still image (docs/conventions.md, "Pixels and
 * samples"). Adding a pass and encoding the average to 8-bit sRGB are one loop over a range of pixels,
 * so that the window can split a pass among threads ({@link FrameRenderer}).
 */
final class Accumulator {

    private int width;
    private int height;
    private double[] sum;
    /** Per pixel: the sum over calls of count x the square of the call's mean luminance, for the noise estimate. */
    private double[] lumaSquares;
    private int passes;
    private int calls;
    private int weight = 1; // passes in the frame being added

    /** Starts over for a width x height view. */
    void reset(int newWidth, int newHeight) {
        if (sum == null || newWidth != width || newHeight != height) {
            sum = null; // the old one can go before the new one is taken
            sum = new double[3 * newWidth * newHeight];
            lumaSquares = new double[newWidth * newHeight];
            width = newWidth;
            height = newHeight;
        } else {
            java.util.Arrays.fill(sum, 0);
            java.util.Arrays.fill(lumaSquares, 0);
        }
        passes = 0;
        calls = 0;
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
        calls++;
        weight = count;
    }

    /**
     * Adds pixels {@code from} (inclusive) to {@code to} (exclusive) of a pass to the sums and writes the
     * average so far, as dithered 8-bit sRGB, to {@code rgb} (0xRRGGBB a pixel). Ranges that do not overlap may be
     * done on different threads at once.
     */
    void addAndEncode(FrameBuffer pass, int[] rgb, int from, int to) {
        addAndEncode(pass, rgb, from, to, ViewTransform.STANDARD);
    }

    /** {@link #addAndEncode(FrameBuffer, int[], int, int)} with the average encoded through a view transform. */
    void addAndEncode(FrameBuffer pass, int[] rgb, int from, int to, ViewTransform view) {
        double[] scratch = new double[3];
        float[] in = pass.rgb();
        double[] s = sum;
        double inverse = 1.0 / passes;
        double w = weight;
        double[] squares = lumaSquares;
        int width = pass.width();
        int x = from % width, y = from / width;
        for (int p = from, i = 3 * from; p < to; p++, i += 3) {
            double luma = luma(in[i], in[i + 1], in[i + 2]);
            squares[p] += w * luma * luma;
            double r = s[i] + w * in[i];
            double g = s[i + 1] + w * in[i + 1];
            double b = s[i + 2] + w * in[i + 2];
            s[i] = r;
            s[i + 1] = g;
            s[i + 2] = b;
            rgb[p] = SrgbEncoder.pixel((float) (r * inverse), (float) (g * inverse), (float) (b * inverse), x, y, view,
                    scratch);
            if (++x == width) {
                x = 0;
                y++;
            }
        }
    }

    /** Encodes pixels {@code from} to {@code to} of the average so far again, through a view transform. */
    void encode(int[] rgb, int from, int to, ViewTransform view) {
        double[] s = sum;
        double inverse = 1.0 / passes;
        double[] scratch = new double[3];
        int x = from % width, y = from / width;
        for (int p = from, i = 3 * from; p < to; p++, i += 3) {
            rgb[p] = SrgbEncoder.pixel((float) (s[i] * inverse), (float) (s[i + 1] * inverse),
                    (float) (s[i + 2] * inverse), x, y, view, scratch);
            if (++x == width) {
                x = 0;
                y++;
            }
        }
    }

    /** The average's size. */
    int width() {
        return width;
    }

    int height() {
        return height;
    }

    /**
     * The noise left in the average, relative to its brightness: the standard error of each pixel's
     * mean luminance, summed over the pixels, over their summed mean luminance; NaN before two calls.
     * A call of c passes is one draw whose variance is the samples' over c, so the spread of the calls'
     * means, each weighted by its c, estimates the samples' variance.
     */
    double relativeNoise() {
        if (calls < 2) {
            return Double.NaN;
        }
        double errors = 0, means = 0, n = passes;
        for (int p = 0, i = 0; p < lumaSquares.length; p++, i += 3) {
            double mean = luma(sum[i], sum[i + 1], sum[i + 2]) / n;
            double variance = Math.max(0, (lumaSquares[p] - n * mean * mean) / (calls - 1));
            errors += Math.sqrt(variance / n);
            means += mean;
        }
        return means > 0 ? errors / means : Double.NaN;
    }

    /** Rec. 709 luminance of linear RGB. */
    private static double luma(double r, double g, double b) {
        return 0.2126 * r + 0.7152 * g + 0.0722 * b;
    }
}
