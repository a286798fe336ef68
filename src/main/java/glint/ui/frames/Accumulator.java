package glint.ui.frames;

import glint.image.FrameBuffer;
import glint.image.ViewTransform;
import glint.render.Convergence;

/**
 * Progressive refinement while the camera is still: adds the sample passes of one view and keeps each pixel's
 * average of its own passes ({@link Convergence}), which after all passes is the still image (docs/conventions.md,
 * "Pixels and samples"). With a noise threshold, pixels that have converged stop receiving passes. Adding a
 * pass and encoding the average to 8-bit sRGB are one loop over a range of pixels, so that the window can split
 * a pass among threads ({@link FrameRenderer}).
 */
final class Accumulator {

    private Convergence pixels;
    private int weight = 1; // passes in the frame being added

    /** Starts over for a width x height view, every pixel refined until the cap. */
    void reset(int newWidth, int newHeight) {
        reset(newWidth, newHeight, 0, Integer.MAX_VALUE);
    }

    /** Starts over for a width x height view whose pixels stop below {@code threshold} (0: none) or at {@code cap}. */
    void reset(int newWidth, int newHeight, double threshold, int cap) {
        if (pixels == null || newWidth != pixels.width() || newHeight != pixels.height()) {
            pixels = null; // the old one can go before the new one is taken
            pixels = new Convergence(newWidth, newHeight, threshold, cap);
        } else {
            pixels.reset(threshold, cap);
        }
    }

    /** Passes added since the last reset: the most a pixel has. */
    int passes() {
        return pixels.passes();
    }

    /** The refinement: which pixels the next pass traces, how many passes a call may trace, whether it is done. */
    Convergence convergence() {
        return pixels;
    }

    /** Counts one more pass; its pixels are then added by {@link #addAndEncode}, range by range. */
    void beginPass() {
        beginPasses(1);
    }

    /** Counts {@code count} more passes, traced in one go: their average is added with weight {@code count}. */
    void beginPasses(int count) {
        weight = count;
    }

    /** The passes begun are added for every pixel: at a round's end the pixels that converged stop. */
    void passesAdded() {
        pixels.passesAdded(weight);
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
        pixels.add(pass, weight, from, to);
        encode(rgb, from, to, view);
    }

    /** Encodes pixels {@code from} to {@code to} of the average so far again, through a view transform. */
    void encode(int[] rgb, int from, int to, ViewTransform view) {
        double[] average = new double[3];
        double[] scratch = new double[3];
        int width = pixels.width();
        int x = from % width, y = from / width;
        for (int p = from; p < to; p++) {
            pixels.average(p, average, 0);
            rgb[p] = SrgbEncoder.pixel((float) average[0], (float) average[1], (float) average[2], x, y, view,
                    scratch);
            if (++x == width) {
                x = 0;
                y++;
            }
        }
    }

    /** The average's size. */
    int width() {
        return pixels.width();
    }

    int height() {
        return pixels.height();
    }

    /** The noise left in the average, relative to its brightness ({@link Convergence#relativeNoise}). */
    double relativeNoise() {
        return pixels.relativeNoise();
    }
}
