package glint.shading;

/**
 * The GGX (Trowbridge-Reitz) microfacet distribution of docs/conventions.md ("cook-torrance", metal
 * and rough glass) as a full lobe: Smith's masking (height-correlated for the pair of directions) and the sampling of
 * the normals visible from a direction (Heitz 2018, "Sampling the GGX Distribution of Visible
 * Normals"). Directions are in the local space of the surface (normal +z), unit length, alpha =
 * roughness^2.
 */
public final class Microfacet {

    /**
     * Below this alpha a conductor is a delta mirror (and glass smooth) to the path integrator: the lobe's width (about
     * alpha radians) is then under 0.06 degrees, less than a pixel of the default view (60 degrees
     * over 800 pixels, 0.075 degrees a pixel), and sampling it only adds fireflies from point
     * lights. Chosen from that geometry, not measured.
     */
    public static final double MIRROR_ALPHA = 1e-3;

    /** Smallest GGX alpha used for a highlight; keeps D(h) finite as roughness goes to 0. */
    static final double MIN_ALPHA = 1e-4;

    private Microfacet() {
    }

    /**
     * The GGX alpha of a roughness from 0 to 1: roughness^2, at least {@link #MIN_ALPHA} above 0; 0 (a
     * mirror, no highlight) at 0.
     */
    public static double alpha(double roughness) {
        return roughness > 0 ? Math.max(roughness * roughness, MIN_ALPHA) : 0;
    }

    /**
     * Smith's Lambda for a direction at cosine {@code cos} (> 0) to the normal. A subnormal cosine
     * counts as the smallest normal one: its 1 / cos would overflow, and G1 = 1 / (1 + inf) = 0 would
     * make the weight G2 / G1 of {@link Conductor#sample} 0 / 0.
     */
    static double lambda(double cos, double alpha) {
        double c = Math.max(cos, Double.MIN_NORMAL);
        double cos2 = c * c;
        return 0.5 * (Math.sqrt(cos2 + alpha * alpha * (1 - cos2)) / c - 1);
    }

    /**
     * What a half vector wo + wi is multiplied by before it is normalised: 2^600 where it is so short
     * (wo and wi mirror images, both grazing to within 1e-154) that the squares of its components
     * would underflow, otherwise 1. A power of two: the direction is unchanged to the last bit.
     */
    static double halfScale(double hx, double hy, double hz) {
        return Math.max(Math.abs(hx), Math.max(Math.abs(hy), Math.abs(hz))) < 0x1p-500 ? 0x1p600 : 1;
    }

    /** Smith's masking of one direction, G1 = 1 / (1 + Lambda). */
    static double g1(double cos, double alpha) {
        return 1 / (1 + lambda(cos, alpha));
    }

    /** Height-correlated masking-shadowing of the pair, G2 = 1 / (1 + Lambda(o) + Lambda(i)). */
    static double g2(double cosOut, double cosIn, double alpha) {
        return 1 / (1 + lambda(cosOut, alpha) + lambda(cosIn, alpha));
    }

    /**
     * A microfacet normal visible from unit world direction wo at surface s ({@code cosOut} = wo.n > 0), sampled
     * by u1 and u2 as {@link #sampleVisibleNormal(double, double, double, double, double, double, double[])} does
     * in s's local frame, into {@code out.half} in world space, with {@code out.frame} as scratch; returns its
     * cosine to s's normal.
     */
    static double sampleVisibleNormal(Surface s, double woX, double woY, double woZ, double cosOut, double alpha,
                                      double u1, double u2, BsdfSample out) {
        ShadingFrame frame = out.frame;
        frame.set(s.nx, s.ny, s.nz);
        double[] h = out.half;
        sampleVisibleNormal(frame.localX(woX, woY, woZ), frame.localY(woX, woY, woZ), cosOut, alpha, u1, u2, h);
        double cosHalf = h[2];
        double hx = frame.worldX(h[0], h[1], h[2]), hy = frame.worldY(h[0], h[1], h[2]), hz = frame.worldZ(h[0], h[1], h[2]);
        h[0] = hx;
        h[1] = hy;
        h[2] = hz;
        return cosHalf;
    }

    /**
     * Samples a microfacet normal visible from local direction wo (wo.z > 0) with density
     * G1(wo) max(0, wo.h) D(h) / wo.z, from two uniform numbers; writes the unit normal to {@code h}.
     */
    static void sampleVisibleNormal(double wox, double woy, double woz, double alpha, double u1, double u2,
                                    double[] h) {
        // the view direction in the space where the distribution is a hemisphere
        double vx = alpha * wox, vy = alpha * woy, vz = woz;
        double inv = 1 / Math.sqrt(vx * vx + vy * vy + vz * vz);
        vx *= inv;
        vy *= inv;
        vz *= inv;
        double lengthSquared = vx * vx + vy * vy;
        double t1x = 1, t1y = 0;
        if (lengthSquared > 0) {
            double invLength = 1 / Math.sqrt(lengthSquared);
            t1x = -vy * invLength;
            t1y = vx * invLength;
        }
        // t2 = v x t1
        double t2x = -vz * t1y, t2y = vz * t1x, t2z = vx * t1y - vy * t1x;
        // a point on the disc, its lower half squeezed to the part of the hemisphere seen from v
        double r = Math.sqrt(u1), phi = 2 * Math.PI * u2;
        double p1 = r * Math.cos(phi), p2 = r * Math.sin(phi);
        double s = 0.5 * (1 + vz);
        p2 = (1 - s) * Math.sqrt(Math.max(0, 1 - p1 * p1)) + s * p2;
        double p3 = Math.sqrt(Math.max(0, 1 - p1 * p1 - p2 * p2));
        double nx = p1 * t1x + p2 * t2x + p3 * vx;
        double ny = p1 * t1y + p2 * t2y + p3 * vy;
        double nz = p2 * t2z + p3 * vz;
        // back to the ellipsoid's space
        double hx = alpha * nx, hy = alpha * ny, hz = Math.max(0, nz);
        double invH = 1 / Math.sqrt(hx * hx + hy * hy + hz * hz);
        h[0] = hx * invH;
        h[1] = hy * invH;
        h[2] = hz * invH;
    }

    /**
     * The density per solid angle of wi = wo mirrored about a visible normal sampled as
     * {@link #sampleVisibleNormal}: G1(wo) D(h) / (4 wo.z), h the half vector.
     */
    static double reflectedPdf(double cosOut, double cosHalf, double alpha) {
        return g1(cosOut, alpha) * Optics.ggx(cosHalf, alpha) / (4 * cosOut);
    }

    /**
     * The density per solid angle of wi = wo refracted through a visible normal h sampled as
     * {@link #sampleVisibleNormal}, at eta = n_o / n_i: G1(wo) D(h) (wo.h) / wo.z, the normal's
     * density, times the Jacobian of the refraction |d h / d wi| = |wi.h| / (eta wo.h + wi.h)^2
     * (Walter et al. 2007, eq. 17, with the indices' ratio eta).
     */
    static double refractedPdf(double cosOut, double cosHalf, double cosOutHalf, double cosInHalf, double eta,
                               double alpha) {
        double denominator = eta * cosOutHalf + cosInHalf;
        return g1(cosOut, alpha) * Optics.ggx(cosHalf, alpha) * cosOutHalf / cosOut * Math.abs(cosInHalf)
                / (denominator * denominator);
    }
}
