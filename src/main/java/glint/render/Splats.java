package glint.render;

import glint.image.FrameBuffer;
import java.util.concurrent.atomic.AtomicLongArray;

/**
 * Light a frame's paths bring to pixels other than their own (a bidirectional path's light-tracing
 * strategy): summed per pixel and channel in fixed point, multiples of 2^-32, so that the sum is the
 * same whatever order the render threads add in, and the image the same bytes at any thread count and
 * tile size. Added into the frame once every tile is done ({@link #addInto}). Thread-safe.
 */
final class Splats {

    /** Fixed point: a value is kept as the nearest multiple of 2^-32. */
    private static final double ONE = 0x1p32;
    /**
     * The most one splat adds to a channel: 2^24, far above any radiance a finished image holds, so that
     * 2^7 splats at the most still sum inside a long; a sum that would overflow stays at the largest.
     */
    static final double LARGEST = 0x1p24;

    private AtomicLongArray sums = new AtomicLongArray(0);
    private int width, height;

    /** Clears the sums for a width x height frame. */
    void clear(int frameWidth, int frameHeight) {
        int size = 3 * frameWidth * frameHeight;
        if (sums.length() != size) {
            sums = new AtomicLongArray(size);
        } else {
            for (int i = 0; i < size; i++) {
                sums.set(i, 0);
            }
        }
        width = frameWidth;
        height = frameHeight;
    }

    /** Adds (r, g, b) to pixel (x, y); a value that is not finite and at least 0 adds nothing. */
    void add(int x, int y, double r, double g, double b) {
        int i = 3 * (y * width + x);
        add(i, r);
        add(i + 1, g);
        add(i + 2, b);
    }

    private void add(int i, double value) {
        if (!(value > 0)) { // 0, negative or NaN
            return;
        }
        long fixed = (long) (Math.min(value, LARGEST) * ONE + 0.5);
        sums.accumulateAndGet(i, fixed, Splats::saturatingSum);
    }

    private static long saturatingSum(long a, long b) {
        long sum = a + b;
        return sum < 0 ? Long.MAX_VALUE : sum; // both are >= 0: a negative sum overflowed
    }

    /** Adds {@code scale} times each pixel's sums into {@code frame}, of the size cleared for. */
    void addInto(FrameBuffer frame, double scale) {
        float[] rgb = frame.rgb();
        for (int i = 0; i < rgb.length; i++) {
            long sum = sums.get(i);
            if (sum != 0) {
                rgb[i] = FrameBuffer.storable(rgb[i] + sum / ONE * scale);
            }
        }
    }

    int width() {
        return width;
    }

    int height() {
        return height;
    }
}
