package glint.ui;

import glint.image.Srgb;
import glint.render.FrameBuffer;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;

/**
 * Turns a frame buffer into an 8-bit sRGB image fast enough for every frame, with exactly the codes
 * of {@link Srgb#to8Bit} (so a saved PNG equals what the window shows): a table by the top bits of
 * the linear value, corrected by the exact threshold of the next code.
 */
final class SrgbEncoder {

    private static final int BUCKETS = 1 << 16;
    /** The code of the smallest value in each bucket [i / BUCKETS, (i + 1) / BUCKETS). */
    private static final byte[] BUCKET_CODE = new byte[BUCKETS];
    /** THRESHOLD[k]: the smallest float whose code is at least k. */
    private static final double[] THRESHOLD = new double[257];

    static {
        for (int k = 1; k <= 255; k++) {
            THRESHOLD[k] = smallestWithCode(k);
        }
        THRESHOLD[256] = Double.POSITIVE_INFINITY;
        for (int i = 0; i < BUCKETS; i++) {
            BUCKET_CODE[i] = (byte) Srgb.to8Bit((float) i / BUCKETS);
        }
    }

    private SrgbEncoder() {
    }

    /** The 8-bit sRGB code of a linear value, equal to {@code Srgb.to8Bit(value)}. */
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

    /** A new image of the frame. */
    static BufferedImage toImage(FrameBuffer frame) {
        BufferedImage image = newImage(frame.width(), frame.height());
        encode(frame, pixels(image), 0, frame.width() * frame.height());
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
        float[] rgb = frame.rgb();
        for (int p = from, i = 3 * from; p < to; p++, i += 3) {
            pixels[p] = code(rgb[i]) << 16 | code(rgb[i + 1]) << 8 | code(rgb[i + 2]);
        }
    }

    private static double smallestWithCode(int k) {
        int lo = 0; // bits of 0.0f: code 0 < k
        int hi = Float.floatToIntBits(1f); // code 255 >= k
        while (hi - lo > 1) {
            int mid = (lo + hi) >>> 1;
            if (Srgb.to8Bit(Float.intBitsToFloat(mid)) >= k) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return Float.intBitsToFloat(hi);
    }
}
