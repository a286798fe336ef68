package glint.study;

import glint.image.FrameBuffer;
import glint.image.Srgb;

/**
 * How far an image is from a reference, four ways: relative MSE on linear values, SSIM on sRGB luma,
 * FLIP (LDR, on the sRGB images) and the mean absolute error in 8-bit sRGB levels, the last three as
 * the physically based references' README defines them.
 *
 * @param relMse relative MSE ({@link RelativeMse})
 * @param ssim   SSIM ({@link Ssim})
 * @param flip   mean FLIP ({@link Flip})
 * @param levels mean over pixels and channels of |a - r| after clamping to [0, 1] and sRGB encoding,
 *               in units of 1/255
 */
public record ImageErrors(double relMse, double ssim, double flip, double levels) {

    public static ImageErrors of(FrameBuffer rendered, FrameBuffer reference) {
        return new ImageErrors(RelativeMse.of(rendered, reference), Ssim.of(rendered, reference),
                Flip.of(rendered, reference), meanLevels(rendered, reference));
    }

    /** The mean absolute difference of the two images in 8-bit sRGB levels (clamped, encoded, x 255). */
    public static double meanLevels(FrameBuffer rendered, FrameBuffer reference) {
        RelativeMse.requireSameSize(rendered, reference);
        float[] a = rendered.rgb(), r = reference.rgb();
        double sum = 0;
        for (int i = 0; i < a.length; i++) {
            sum += Math.abs(Srgb.encode(a[i]) - Srgb.encode(r[i]));
        }
        return 255 * sum / a.length;
    }

    /**
     * The image made smaller by {@code factor} in each direction, each pixel the mean of the
     * factor x factor pixels it covers: what a renderer that averages its samples over the pixel
     * (a box filter) gives at the smaller size.
     */
    public static FrameBuffer averaged(FrameBuffer image, int factor) {
        if (factor < 1 || image.width() % factor != 0 || image.height() % factor != 0) {
            throw new IllegalArgumentException(image.width() + "x" + image.height() + " does not divide by " + factor);
        }
        int w = image.width() / factor, h = image.height() / factor;
        FrameBuffer out = new FrameBuffer(w, h);
        double cells = factor * factor;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double r = 0, g = 0, b = 0;
                for (int dy = 0; dy < factor; dy++) {
                    for (int dx = 0; dx < factor; dx++) {
                        r += image.get(x * factor + dx, y * factor + dy, 0);
                        g += image.get(x * factor + dx, y * factor + dy, 1);
                        b += image.get(x * factor + dx, y * factor + dy, 2);
                    }
                }
                out.set(x, y, r / cells, g / cells, b / cells);
            }
        }
        return out;
    }
}
