package glint.study;

import glint.shading.Optics;

/**
 * The specular lobe of the cook-torrance model, Glint's and the textbook's, as functions of the
 * cosines a renderer has at hand, plus its directional albedo (the fraction of light from one
 * direction that the lobe reflects, with Fresnel = 1): at most 1 for an energy-conserving lobe.
 *
 * <p>Glint: GGX with alpha = roughness^2 clamped to at least 1e-4 (glint.shading.Microfacet.alpha), no lobe at
 * roughness 0 (a pure mirror), height-correlated Smith visibility. (The renderer's Conductor takes
 * alpha below Microfacet.MIRROR_ALPHA, 1e-3, for a mirror and has no lobe there.) Textbook (Cook and Torrance 1982,
 * as in the 2020 report): Beckmann distribution with m = roughness, the V-groove masking
 * min(1, 2 n.h n.v / v.h, 2 n.h n.l / v.h), divided by 4 n.l n.v, used as it is at any roughness.
 */
public final class Microfacet {

    /** Glint's smallest GGX alpha (glint.shading.Microfacet.MIN_ALPHA is package-private; this mirrors it). */
    public static final double GLINT_MIN_ALPHA = 1e-4;

    private Microfacet() {
    }

    /**
     * Glint's lobe times n.l through the functions Conductor evaluates it with: D(h) V(l, v) n.l; 0
     * when the light or the viewer is below the surface or the roughness is 0.
     */
    public static double glint(double cosHalf, double cosLight, double cosView, double roughness) {
        if (roughness <= 0 || cosLight <= 0 || cosView <= 0) {
            return 0;
        }
        double alpha = Math.max(roughness * roughness, GLINT_MIN_ALPHA);
        return Optics.ggx(cosHalf, alpha) * Optics.smithVisibility(cosLight, cosView, alpha) * cosLight;
    }

    /** The textbook lobe times n.l: D_Beckmann(h) G / (4 n.l n.v) n.l, evaluated as written. */
    public static double textbook(double cosHalf, double cosLight, double cosView, double cosViewHalf, double roughness) {
        double m2 = roughness * roughness;
        double c2 = cosHalf * cosHalf;
        double d = Math.exp((c2 - 1) / (c2 * m2)) / (Math.PI * m2 * c2 * c2);
        double g = Math.min(1, Math.min(2 * cosHalf * cosView / cosViewHalf, 2 * cosHalf * cosLight / cosViewHalf));
        return d * g / (4 * cosLight * cosView) * cosLight;
    }

    /**
     * Directional albedo of Glint's lobe for a view at {@code cosView}: the integral of D V n.l over
     * the hemisphere of light directions, by sampling the half-vector from the GGX distribution on an
     * n x n stratified grid (midpoints), so the estimate is deterministic and exact in the limit.
     */
    public static double glintAlbedo(double cosView, double roughness, int n) {
        double alpha = Math.max(roughness * roughness, GLINT_MIN_ALPHA);
        double a2 = alpha * alpha;
        double sinView = Math.sqrt(Math.max(0, 1 - cosView * cosView));
        double sum = 0;
        for (int i = 0; i < n; i++) {
            double u = (i + 0.5) / n;
            double cos2 = (1 - u) / (1 + (a2 - 1) * u); // GGX: pdf(h) = D(h) n.h
            double cosH = Math.sqrt(cos2), sinH = Math.sqrt(Math.max(0, 1 - cos2));
            for (int j = 0; j < n; j++) {
                double phi = 2 * Math.PI * (j + 0.5) / n;
                double hx = sinH * Math.cos(phi), hy = sinH * Math.sin(phi), hz = cosH;
                double vh = sinView * hx + cosView * hz;
                if (vh <= 0) {
                    continue;
                }
                double lz = 2 * vh * hz - cosView;
                if (lz <= 0) {
                    continue;
                }
                double pdfLight = ggx(cosH, a2) * cosH / (4 * vh); // of the reflected direction
                sum += glint(cosH, lz, cosView, roughness) / pdfLight;
            }
        }
        return sum / ((double) n * n);
    }

    /**
     * Directional albedo of the textbook lobe, sampling the half-vector from the Beckmann distribution
     * (tan^2 = -m^2 ln(1 - u)) on the same kind of grid.
     */
    public static double textbookAlbedo(double cosView, double roughness, int n) {
        double m2 = roughness * roughness;
        double sinView = Math.sqrt(Math.max(0, 1 - cosView * cosView));
        double sum = 0;
        for (int i = 0; i < n; i++) {
            double u = (i + 0.5) / n;
            double tan2 = -m2 * Math.log(1 - u);
            double cos2 = 1 / (1 + tan2);
            double cosH = Math.sqrt(cos2), sinH = Math.sqrt(Math.max(0, 1 - cos2));
            double pdfHalf = Math.exp(-tan2 / m2) / (Math.PI * m2 * cos2 * cos2) * cosH;
            for (int j = 0; j < n; j++) {
                double phi = 2 * Math.PI * (j + 0.5) / n;
                double hx = sinH * Math.cos(phi), hy = sinH * Math.sin(phi), hz = cosH;
                double vh = sinView * hx + cosView * hz;
                if (vh <= 0) {
                    continue;
                }
                double lz = 2 * vh * hz - cosView;
                if (lz <= 0) {
                    continue;
                }
                sum += textbook(cosH, lz, cosView, vh, roughness) / (pdfHalf / (4 * vh));
            }
        }
        return sum / ((double) n * n);
    }

    /**
     * Evaluates both lobes at every pairing of view and light directions at the angles given (degrees
     * from the normal, 90 meaning exactly grazing: cosine 0) and azimuths 0, 90 and 180 degrees apart,
     * and counts the values that are not finite numbers: {glint, textbook, evaluations}.
     */
    public static int[] nonFinite(double[] angles, double roughness) {
        int glintBad = 0, textbookBad = 0, total = 0;
        for (double tv : angles) {
            for (double tl : angles) {
                for (double phi : new double[] {0, 90, 180}) {
                    double cv = cosOf(tv), sv = sinOf(tv), cl = cosOf(tl), sl = sinOf(tl);
                    double lx = sl * Math.cos(Math.toRadians(phi)), ly = sl * Math.sin(Math.toRadians(phi));
                    double hx = sv + lx, hy = ly, hz = cv + cl;
                    double len = Math.sqrt(hx * hx + hy * hy + hz * hz);
                    if (len == 0) {
                        continue;
                    }
                    double cosHalf = hz / len, cosViewHalf = (sv * hx + cv * hz) / len;
                    total++;
                    glintBad += Double.isFinite(glint(cosHalf, cl, cv, roughness)) ? 0 : 1;
                    textbookBad += Double.isFinite(textbook(cosHalf, cl, cv, cosViewHalf, roughness)) ? 0 : 1;
                }
            }
        }
        return new int[] {glintBad, textbookBad, total};
    }

    private static double cosOf(double degrees) {
        return degrees >= 90 ? 0 : Math.cos(Math.toRadians(degrees));
    }

    private static double sinOf(double degrees) {
        return degrees >= 90 ? 1 : Math.sin(Math.toRadians(degrees));
    }

    /** GGX D written out here, independent of {@link Optics#ggx}, for the sampling density. */
    private static double ggx(double cosHalf, double a2) {
        double k = cosHalf * cosHalf * (a2 - 1) + 1;
        return a2 / (Math.PI * k * k);
    }
}
