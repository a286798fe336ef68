package glint.study;

import glint.image.FrameBuffer;
import glint.image.Srgb;

/**
 * The structural similarity index of Wang, Bovik, Sheikh and Simoncelli (IEEE TIP 2004), as in their
 * reference implementation: an 11 x 11 Gaussian window of sigma 1.5, K1 = 0.01, K2 = 0.03, dynamic
 * range L = 1, the mean over every window position that fits inside the image ("valid"). It is
 * computed on what a viewer sees: the luma Y' = 0.2126 R' + 0.7152 G' + 0.0722 B' of the sRGB-encoded
 * values (each channel clamped to [0, 1], docs/conventions.md, "Units and colour"). Java has no
 * maintained SSIM library, so this is Glint's own.
 */
public final class Ssim {

    static final int WINDOW = 11;
    static final double SIGMA = 1.5;
    static final double C1 = 0.01 * 0.01;
    static final double C2 = 0.03 * 0.03;

    private Ssim() {
    }

    /** SSIM of two frames of the same size, on sRGB luma. */
    public static double of(FrameBuffer a, FrameBuffer b) {
        if (a.width() != b.width() || a.height() != b.height()) {
            throw new IllegalArgumentException("image sizes differ");
        }
        return of(luma(a), luma(b), a.width(), a.height());
    }

    /** SSIM of two single-channel images in [0, 1], row-major, width x height. */
    public static double of(double[] x, double[] y, int width, int height) {
        if (width < WINDOW || height < WINDOW) {
            throw new IllegalArgumentException("SSIM needs an image of at least " + WINDOW + "x" + WINDOW);
        }
        if (x.length != width * height || y.length != width * height) {
            throw new IllegalArgumentException("image arrays do not match " + width + "x" + height);
        }
        int n = width * height;
        double[] xx = new double[n], yy = new double[n], xy = new double[n];
        for (int i = 0; i < n; i++) {
            xx[i] = x[i] * x[i];
            yy[i] = y[i] * y[i];
            xy[i] = x[i] * y[i];
        }
        double[] kernel = gaussian();
        double[] mx = blur(x, width, height, kernel), my = blur(y, width, height, kernel);
        double[] sxx = blur(xx, width, height, kernel), syy = blur(yy, width, height, kernel);
        double[] sxy = blur(xy, width, height, kernel);
        double sum = 0;
        for (int i = 0; i < mx.length; i++) {
            double ux = mx[i], uy = my[i];
            double vx = sxx[i] - ux * ux, vy = syy[i] - uy * uy, cov = sxy[i] - ux * uy;
            sum += (2 * ux * uy + C1) * (2 * cov + C2) / ((ux * ux + uy * uy + C1) * (vx + vy + C2));
        }
        return sum / mx.length;
    }

    /** The sRGB luma of each pixel, rows top to bottom. */
    public static double[] luma(FrameBuffer frame) {
        float[] rgb = frame.rgb();
        double[] y = new double[frame.width() * frame.height()];
        for (int i = 0; i < y.length; i++) {
            y[i] = 0.2126 * Srgb.encode(rgb[3 * i]) + 0.7152 * Srgb.encode(rgb[3 * i + 1])
                    + 0.0722 * Srgb.encode(rgb[3 * i + 2]);
        }
        return y;
    }

    static double[] gaussian() {
        double[] k = new double[WINDOW];
        double sum = 0;
        for (int i = 0; i < WINDOW; i++) {
            double d = i - WINDOW / 2;
            k[i] = Math.exp(-d * d / (2 * SIGMA * SIGMA));
            sum += k[i];
        }
        for (int i = 0; i < WINDOW; i++) {
            k[i] /= sum;
        }
        return k;
    }

    /** Separable weighted means over every window that fits: (w - 10) x (h - 10) values. */
    private static double[] blur(double[] image, int width, int height, double[] k) {
        int ow = width - WINDOW + 1, oh = height - WINDOW + 1;
        double[] rows = new double[ow * height];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < ow; x++) {
                double s = 0;
                for (int i = 0; i < WINDOW; i++) {
                    s += k[i] * image[y * width + x + i];
                }
                rows[y * ow + x] = s;
            }
        }
        double[] out = new double[ow * oh];
        for (int y = 0; y < oh; y++) {
            for (int x = 0; x < ow; x++) {
                double s = 0;
                for (int i = 0; i < WINDOW; i++) {
                    s += k[i] * rows[(y + i) * ow + x];
                }
                out[y * ow + x] = s;
            }
        }
        return out;
    }
}
