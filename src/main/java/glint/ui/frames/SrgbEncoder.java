package glint.ui.frames;

import glint.image.Dither;
import glint.image.FrameBuffer;
import glint.image.Srgb;
import glint.image.ViewTransform;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;

/**
 * Turns a frame buffer into an 8-bit sRGB image fast enough for every frame, with exactly the dithered
 * codes of {@link Srgb#to8Bit(double, int)} (so a saved PNG equals what the window shows): the rounded code
 * from a table by the top bits of the linear value, corrected by the exact threshold of the next code,
 * then the dithered code, one of the two codes around the value, by the exact threshold of the upper one
 * at the pixel's dither level. Through a view transform other than the plain one, the exposure scales the
 * value first (the standard curve then takes the same tables) or the transform encodes it itself
 * ({@link ViewTransform#pixel}), as a PNG's writer does.
 */
final class SrgbEncoder {

    private static final int BUCKETS = 1 << 16;
    /** The rounded code of the smallest value in each bucket [i / BUCKETS, (i + 1) / BUCKETS). */
    private static final byte[] BUCKET_CODE = new byte[BUCKETS];
    /** THRESHOLD[k]: the smallest float whose rounded code is at least k. */
    private static final double[] THRESHOLD = new double[257];
    /** DITHERED[level][k]: the smallest float whose code dithered at that level is at least k. */
    private static final double[][] DITHERED = new double[Dither.LEVELS][257];

    static {
        for (int k = 1; k <= 255; k++) {
            int code = k;
            THRESHOLD[k] = smallestWith(v -> Srgb.to8Bit(v) >= code);
        }
        THRESHOLD[256] = Double.POSITIVE_INFINITY;
        for (int level = 0; level < Dither.LEVELS; level++) {
            int at = level;
            DITHERED[level][0] = Double.NEGATIVE_INFINITY;
            for (int k = 1; k <= 255; k++) {
                int code = k;
                DITHERED[level][k] = smallestWith(v -> Srgb.to8Bit(v, at) >= code);
            }
            DITHERED[level][256] = Double.POSITIVE_INFINITY;
        }
        for (int i = 0; i < BUCKETS; i++) {
            BUCKET_CODE[i] = (byte) Srgb.to8Bit((float) i / BUCKETS);
        }
    }

    private SrgbEncoder() {
    }

    /** The rounded 8-bit sRGB code of a linear value, equal to {@code Srgb.to8Bit(value)}. */
    static int code(float linear) {
        if (!(linear > 0)) {
            return 0; // zero, negative and NaN
        }
        if (linear >= 1) {
            return 255;
        }
        int code = BUCKET_CODE[(int) (linear * BUCKETS)] & 0xff;
        return linear >= THRESHOLD[code + 1] ? code + 1 : code;
    }

    /**
     * The 8-bit sRGB code of a linear value dithered at {@code level}, equal to {@code Srgb.to8Bit(value, level)}:
     * below half a code's offset it is the rounded code or the one under it, above it the rounded one or the
     * one over it.
     */
    static int code(float linear, int level) {
        if (!(linear > 0)) {
            return 0;
        }
        if (linear >= 1) {
            return 255;
        }
        int upper = code(linear) + (level < Dither.LEVELS / 2 ? 0 : 1);
        return linear >= DITHERED[level][upper] ? upper : upper - 1;
    }

    /** Pixel (x, y) of linear red, green and blue as 0xRRGGBB, dithered. */
    static int pixel(float r, float g, float b, int x, int y) {
        int levels = Dither.levels(x, y);
        return code(r, Dither.channel(levels, 0)) << 16 | code(g, Dither.channel(levels, 1)) << 8
                | code(b, Dither.channel(levels, 2));
    }

    /** Pixel (x, y) of linear red, green and blue through a view transform, as 0xRRGGBB, dithered. */
    static int pixel(float r, float g, float b, int x, int y, ViewTransform view, double[] scratch) {
        if (view.isIdentity()) {
            return pixel(r, g, b, x, y);
        }
        if (view.tone() == ViewTransform.Tone.STANDARD) {
            return pixel(view.exposed(r), view.exposed(g), view.exposed(b), x, y);
        }
        return view.pixel(r, g, b, Dither.levels(x, y), scratch);
    }

    /** A new image of the frame. */
    static BufferedImage toImage(FrameBuffer frame) {
        return toImage(frame, ViewTransform.STANDARD);
    }

    /** A new image of the frame through a view transform. */
    static BufferedImage toImage(FrameBuffer frame, ViewTransform view) {
        BufferedImage image = newImage(frame.width(), frame.height());
        encode(frame, pixels(image), 0, frame.width() * frame.height(), view);
        return image;
    }

    /** A new 8-bit RGB image, black. */
    static BufferedImage newImage(int width, int height) {
        return new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
    }

    /** The pixels of an image made by {@link #newImage}, 0xRRGGBB each, row by row. */
    static int[] pixels(BufferedImage image) {
        return ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
    }

    /** Encodes pixels {@code from} (inclusive) to {@code to} (exclusive) of the frame into {@code pixels}. */
    static void encode(FrameBuffer frame, int[] pixels, int from, int to) {
        encode(frame, pixels, from, to, ViewTransform.STANDARD);
    }

    /** Encodes pixels {@code from} (inclusive) to {@code to} (exclusive) of the frame through a view transform. */
    static void encode(FrameBuffer frame, int[] pixels, int from, int to, ViewTransform view) {
        float[] rgb = frame.rgb();
        int width = frame.width();
        int x = from % width, y = from / width;
        double[] scratch = new double[3];
        for (int p = from, i = 3 * from; p < to; p++, i += 3) {
            pixels[p] = pixel(rgb[i], rgb[i + 1], rgb[i + 2], x, y, view, scratch);
            if (++x == width) {
                x = 0;
                y++;
            }
        }
    }

    private interface FloatTest {
        boolean holds(float value);
    }

    /** The smallest float in [0, 1] for which {@code test} holds, given that it holds at 1 and not at 0 and only grows. */
    private static double smallestWith(FloatTest test) {
        int lo = 0; // bits of 0.0f
        int hi = Float.floatToIntBits(1f);
        while (hi - lo > 1) {
            int mid = (lo + hi) >>> 1;
            if (test.holds(Float.intBitsToFloat(mid))) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return Float.intBitsToFloat(hi);
    }
}
