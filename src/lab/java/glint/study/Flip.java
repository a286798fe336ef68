package glint.study;

import glint.image.FrameBuffer;
import glint.image.Srgb;

/**
 * LDR-FLIP, the perceptual difference of Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström and
 * Fairchild ("FLIP: A Difference Evaluator for Alternating Images", HPG 2020), computed on the sRGB
 * images (each channel clamped to [0, 1] and encoded) for a viewer at 67 pixels a degree (a 0.7 m
 * wide 3840-pixel monitor seen from 0.7 m, the paper's default). Per pixel, a colour error from
 * images filtered by the eye's contrast sensitivity (in YCxCz, then HyAB on Hunt-adjusted L*a*b*) is
 * raised to the power 1 - a feature error (edges and points of the luminance that one image has and
 * the other lacks); the value reported is the mean over the pixels, from 0 (the same) towards 1. The
 * image's border is extended by its edge pixels for the filters.
 */
public final class Flip {

    /** Pixels per degree of visual angle: 3840 pixels over 0.7 m seen from 0.7 m. */
    public static final double PIXELS_PER_DEGREE = 3840 * Math.PI / 180;

    private static final double QC = 0.7, PC = 0.4, PT = 0.95, QF = 0.5, FEATURE_WIDTH = 0.082;
    /** Contrast sensitivity as sums of two Gaussians, a and b per channel (achromatic, red-green, blue-yellow). */
    private static final double[][] CSF = {{1, 0.0047, 0, 1e-5}, {1, 0.0053, 0, 1e-5}, {34.1, 0.04, 13.5, 0.025}};
    /** Linear sRGB to CIE XYZ (D65); its inverse and the white point (XYZ of RGB 1, 1, 1) follow. */
    private static final double[][] RGB_TO_XYZ = {
        {0.4124564, 0.3575761, 0.1804375}, {0.2126729, 0.7151522, 0.0721750}, {0.0193339, 0.1191920, 0.9503041}};
    private static final double[][] XYZ_TO_RGB = inverse(RGB_TO_XYZ);
    private static final double[] WHITE = {sum(RGB_TO_XYZ[0]), sum(RGB_TO_XYZ[1]), sum(RGB_TO_XYZ[2])};
    /** The largest colour difference: HyAB between Hunt-adjusted green and blue, to the power QC. */
    private static final double C_MAX = Math.pow(hyab(huntLab(0, 1, 0), huntLab(0, 0, 1)), QC);

    private Flip() {
    }

    /** The mean FLIP of {@code test} against {@code reference}, both linear images of the same size. */
    public static double of(FrameBuffer test, FrameBuffer reference) {
        if (test.width() != reference.width() || test.height() != reference.height()) {
            throw new IllegalArgumentException("image sizes differ: " + test.width() + "x" + test.height()
                    + " vs " + reference.width() + "x" + reference.height());
        }
        double[] map = errorMap(encoded(reference), encoded(test), test.width(), test.height());
        double sum = 0;
        for (double e : map) {
            sum += e;
        }
        return sum / map.length;
    }

    /** The FLIP of every pixel, from sRGB-encoded images (3 values a pixel, rows top to bottom, in [0, 1]). */
    static double[] errorMap(double[] referenceSrgb, double[] testSrgb, int width, int height) {
        double[][] ref = ycxcz(referenceSrgb), test = ycxcz(testSrgb);
        double[] refLab = filteredLab(ref, width, height), testLab = filteredLab(test, width, height);
        double[] refFeatures = features(ref[0], width, height), testFeatures = features(test[0], width, height);
        int n = width * height;
        double[] out = new double[n];
        for (int i = 0; i < n; i++) {
            double colour = redistribute(Math.pow(hyab(refLab, testLab, 3 * i), QC));
            double edge = Math.abs(refFeatures[2 * i] - testFeatures[2 * i]);
            double point = Math.abs(refFeatures[2 * i + 1] - testFeatures[2 * i + 1]);
            double feature = Math.pow(Math.max(edge, point) / Math.sqrt(2), QF);
            out[i] = Math.pow(colour, 1 - feature);
        }
        return out;
    }

    private static double[] encoded(FrameBuffer frame) {
        float[] rgb = frame.rgb();
        double[] out = new double[rgb.length];
        for (int i = 0; i < rgb.length; i++) {
            out[i] = Srgb.encode(rgb[i]);
        }
        return out;
    }

    /** The three planes Y, Cx, Cz of sRGB values: Y = 116 Y/Yn - 16, Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn). */
    private static double[][] ycxcz(double[] srgb) {
        int n = srgb.length / 3;
        double[][] planes = new double[3][n];
        double[] xyz = new double[3];
        for (int i = 0; i < n; i++) {
            toXyz(linear(srgb[3 * i]), linear(srgb[3 * i + 1]), linear(srgb[3 * i + 2]), xyz);
            double x = xyz[0] / WHITE[0], y = xyz[1] / WHITE[1], z = xyz[2] / WHITE[2];
            planes[0][i] = 116 * y - 16;
            planes[1][i] = 500 * (x - y);
            planes[2][i] = 200 * (y - z);
        }
        return planes;
    }

    /** Each plane filtered by its contrast sensitivity, back to linear RGB clamped to [0, 1], then Hunt-adjusted L*a*b*. */
    private static double[] filteredLab(double[][] ycxcz, int width, int height) {
        int radius = (int) Math.ceil(3 * Math.sqrt(0.04 / (2 * Math.PI * Math.PI)) * PIXELS_PER_DEGREE);
        double[][] filtered = new double[3][];
        for (int c = 0; c < 3; c++) {
            filtered[c] = contrastFiltered(ycxcz[c], width, height, CSF[c], radius);
        }
        int n = width * height;
        double[] lab = new double[3 * n];
        double[] rgb = new double[3], xyz = new double[3];
        for (int i = 0; i < n; i++) {
            double yy = (filtered[0][i] + 16) / 116;
            xyz[0] = WHITE[0] * (filtered[1][i] / 500 + yy);
            xyz[1] = WHITE[1] * yy;
            xyz[2] = WHITE[2] * (yy - filtered[2][i] / 200);
            for (int r = 0; r < 3; r++) {
                double v = XYZ_TO_RGB[r][0] * xyz[0] + XYZ_TO_RGB[r][1] * xyz[1] + XYZ_TO_RGB[r][2] * xyz[2];
                rgb[r] = Math.max(0, Math.min(1, v));
            }
            double[] hunt = huntLab(rgb[0], rgb[1], rgb[2]);
            System.arraycopy(hunt, 0, lab, 3 * i, 3);
        }
        return lab;
    }

    /**
     * The plane convolved with a1 sqrt(pi/b1) exp(-pi^2 r^2 / b1) + a2 sqrt(pi/b2) exp(-pi^2 r^2 / b2),
     * r in degrees, over a (2 radius + 1)^2 square normalised to sum 1: each Gaussian term separably.
     */
    private static double[] contrastFiltered(double[] plane, int width, int height, double[] csf, int radius) {
        double[][] terms = new double[2][];
        double[] weights = new double[2];
        double total = 0;
        for (int t = 0; t < 2; t++) {
            double a = csf[2 * t], b = csf[2 * t + 1];
            terms[t] = new double[2 * radius + 1];
            double line = 0;
            for (int k = -radius; k <= radius; k++) {
                double x = k / PIXELS_PER_DEGREE;
                terms[t][k + radius] = Math.exp(-Math.PI * Math.PI * x * x / b);
                line += terms[t][k + radius];
            }
            weights[t] = a * Math.sqrt(Math.PI / b);
            total += weights[t] * line * line;
        }
        double[] out = new double[plane.length];
        for (int t = 0; t < 2; t++) {
            if (weights[t] == 0) {
                continue;
            }
            double[] term = convolve(plane, width, height, terms[t], terms[t]);
            double w = weights[t] / total;
            for (int i = 0; i < out.length; i++) {
                out[i] += w * term[i];
            }
        }
        return out;
    }

    /**
     * Per pixel, two values: the length of the gradient of the normalised luminance Y/Yn (first
     * derivatives of a Gaussian of sigma = 0.5 x 0.082 degrees) and of its second derivatives, each
     * kernel scaled so that its positive weights sum to 1 and its negative ones to -1.
     */
    private static double[] features(double[] y, int width, int height) {
        double[] luminance = new double[y.length];
        for (int i = 0; i < y.length; i++) {
            luminance[i] = (y[i] + 16) / 116;
        }
        double sigma = 0.5 * FEATURE_WIDTH * PIXELS_PER_DEGREE;
        int radius = (int) Math.ceil(3 * sigma);
        double[] gauss = new double[2 * radius + 1], first = new double[2 * radius + 1], second = new double[2 * radius + 1];
        for (int k = -radius; k <= radius; k++) {
            double g = Math.exp(-k * k / (2 * sigma * sigma));
            gauss[k + radius] = g;
            first[k + radius] = -k * g;
            second[k + radius] = (k * k / (sigma * sigma) - 1) * g;
        }
        signedNormalise(first, sum(gauss));
        signedNormalise(second, sum(gauss));
        double[] edgeX = convolve(luminance, width, height, first, gauss);
        double[] edgeY = convolve(luminance, width, height, gauss, first);
        double[] pointX = convolve(luminance, width, height, second, gauss);
        double[] pointY = convolve(luminance, width, height, gauss, second);
        double[] out = new double[2 * y.length];
        for (int i = 0; i < y.length; i++) {
            out[2 * i] = Math.hypot(edgeX[i], edgeY[i]);
            out[2 * i + 1] = Math.hypot(pointX[i], pointY[i]);
        }
        return out;
    }

    /**
     * Scales the signed factor f of a separable kernel f(x) g(y), g positive with sum {@code across}, so
     * that the 2D kernel's positive weights sum to 1 and its negative ones to -1.
     */
    private static void signedNormalise(double[] f, double across) {
        double positive = 0, negative = 0;
        for (double v : f) {
            if (v > 0) {
                positive += v;
            } else {
                negative -= v;
            }
        }
        for (int i = 0; i < f.length; i++) {
            f[i] /= (f[i] > 0 ? positive : negative) * across;
        }
    }

    /** The plane convolved with alongX(x) alongY(y), centred, the border extended by its edge pixels. */
    private static double[] convolve(double[] plane, int width, int height, double[] alongX, double[] alongY) {
        int rx = alongX.length / 2, ry = alongY.length / 2;
        double[] rows = new double[plane.length];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                double s = 0;
                for (int k = -rx; k <= rx; k++) {
                    s += alongX[k + rx] * plane[y * width + Math.max(0, Math.min(width - 1, x - k))];
                }
                rows[y * width + x] = s;
            }
        }
        double[] out = new double[plane.length];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                double s = 0;
                for (int k = -ry; k <= ry; k++) {
                    s += alongY[k + ry] * rows[Math.max(0, Math.min(height - 1, y - k)) * width + x];
                }
                out[y * width + x] = s;
            }
        }
        return out;
    }

    /** Colour differences up to PC x C_MAX map linearly onto [0, PT], the rest onto [PT, 1]. */
    private static double redistribute(double difference) {
        double knee = PC * C_MAX;
        return difference < knee ? PT / knee * difference : PT + (difference - knee) / (C_MAX - knee) * (1 - PT);
    }

    private static double hyab(double[] a, double[] b, int i) {
        double da = a[i + 1] - b[i + 1], db = a[i + 2] - b[i + 2];
        return Math.abs(a[i] - b[i]) + Math.sqrt(da * da + db * db);
    }

    private static double hyab(double[] a, double[] b) {
        return hyab(a, b, 0);
    }

    /** CIE L*a*b* of linear RGB (white: RGB 1, 1, 1), with Hunt's adjustment a* and b* scaled by L* / 100. */
    private static double[] huntLab(double r, double g, double b) {
        double[] xyz = new double[3];
        toXyz(r, g, b, xyz);
        double fx = labF(xyz[0] / WHITE[0]), fy = labF(xyz[1] / WHITE[1]), fz = labF(xyz[2] / WHITE[2]);
        double lightness = 116 * fy - 16;
        return new double[] {lightness, 0.01 * lightness * 500 * (fx - fy), 0.01 * lightness * 200 * (fy - fz)};
    }

    private static double labF(double t) {
        double delta = 6.0 / 29;
        return t > delta * delta * delta ? Math.cbrt(t) : t / (3 * delta * delta) + 4.0 / 29;
    }

    private static void toXyz(double r, double g, double b, double[] xyz) {
        for (int row = 0; row < 3; row++) {
            xyz[row] = RGB_TO_XYZ[row][0] * r + RGB_TO_XYZ[row][1] * g + RGB_TO_XYZ[row][2] * b;
        }
    }

    /** The sRGB decoding of IEC 61966-2-1. */
    private static double linear(double encoded) {
        return encoded <= 0.04045 ? encoded / 12.92 : Math.pow((encoded + 0.055) / 1.055, 2.4);
    }

    private static double sum(double[] values) {
        double s = 0;
        for (double v : values) {
            s += v;
        }
        return s;
    }

    private static double[][] inverse(double[][] m) {
        double a = m[0][0], b = m[0][1], c = m[0][2], d = m[1][0], e = m[1][1], f = m[1][2];
        double g = m[2][0], h = m[2][1], i = m[2][2];
        double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
        return new double[][] {
            {(e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det},
            {(f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det},
            {(d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det}};
    }
}
