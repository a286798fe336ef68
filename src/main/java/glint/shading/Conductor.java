package glint.shading;

/**
 * A metal (docs/conventions.md, "cook-torrance"): the GGX microfacet lobe with Schlick's Fresnel, F0 =
 * the material's colour, and height-correlated Smith masking; a delta mirror below
 * {@link Microfacet#MIRROR_ALPHA}. Whitted's integrator follows its mirror direction
 * ({@link MetalResponse}) and lights its lobe (the highlight).
 */
public final class Conductor implements Bsdf {

    /** Where its material's GGX alpha stands among its numbers ({@link Materials#parameter}). */
    private static final int ALPHA = 0;

    /** The numbers a conductor reads of its material, in order: its GGX alpha ({@link Microfacet#alpha}). */
    public static double[] parameters(double roughness) {
        return new double[] {Microfacet.alpha(roughness)};
    }

    /**
     * f = D(h) G2 F(wo.h) / (4 wo.n wi.n), the GGX lobe, finite while either cosine is at least 1e-300;
     * none below {@link Microfacet#MIRROR_ALPHA}, a mirror.
     */
    @Override
    public void evaluate(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY,
                         double wiZ, Rgb f) {
        int material = s.material;
        double alpha = m.parameter(material, ALPHA);
        double cosOut = woX * s.nx + woY * s.ny + woZ * s.nz, cosIn = wiX * s.nx + wiY * s.ny + wiZ * s.nz;
        if (alpha < Microfacet.MIRROR_ALPHA || !(cosOut > 0) || !(cosIn > 0)) {
            f.set(0, 0, 0);
            return;
        }
        double scale = Microfacet.halfScale(woX + wiX, woY + wiY, woZ + wiZ);
        double hx = (woX + wiX) * scale, hy = (woY + wiY) * scale, hz = (woZ + wiZ) * scale;
        double inv = 1 / Math.sqrt(hx * hx + hy * hy + hz * hz);
        double cosHalf = (hx * s.nx + hy * s.ny + hz * s.nz) * inv;
        double cosOutHalf = Math.max(0, (hx * woX + hy * woY + hz * woZ) * inv);
        // G2 / (4 wo.n wi.n) as one term: the product of two grazing cosines would underflow to 0
        double lobe = Optics.ggx(cosHalf, alpha) * Optics.smithVisibility(cosIn, cosOut, alpha);
        f.set(lobe * Optics.schlick(m.color(material, 0), cosOutHalf),
                lobe * Optics.schlick(m.color(material, 1), cosOutHalf),
                lobe * Optics.schlick(m.color(material, 2), cosOutHalf));
    }

    @Override
    public double pdf(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY,
                      double wiZ) {
        double alpha = m.parameter(s.material, ALPHA);
        double cosOut = woX * s.nx + woY * s.ny + woZ * s.nz, cosIn = wiX * s.nx + wiY * s.ny + wiZ * s.nz;
        if (alpha < Microfacet.MIRROR_ALPHA || !(cosOut > 0) || !(cosIn > 0)) {
            return 0;
        }
        double scale = Microfacet.halfScale(woX + wiX, woY + wiY, woZ + wiZ);
        double hx = (woX + wiX) * scale, hy = (woY + wiY) * scale, hz = (woZ + wiZ) * scale;
        double cosHalf = (hx * s.nx + hy * s.ny + hz * s.nz) / Math.sqrt(hx * hx + hy * hy + hz * hz);
        return Microfacet.reflectedPdf(cosOut, cosHalf, alpha);
    }

    /**
     * The mirror direction below {@link Microfacet#MIRROR_ALPHA}, weight Schlick's F; otherwise wo
     * mirrored about a visible GGX normal, weight F G2 / G1(wo).
     */
    @Override
    public boolean sample(Materials m, Surface s, double woX, double woY, double woZ, double u1, double u2,
                          double uLobe, BsdfSample out) {
        int material = s.material;
        double alpha = m.parameter(material, ALPHA);
        double cosOut = s.cosIncident;
        if (alpha < Microfacet.MIRROR_ALPHA) {
            mirror(s, woX, woY, woZ, out);
            out.setWeight(Optics.schlick(m.color(material, 0), cosOut), Optics.schlick(m.color(material, 1), cosOut),
                    Optics.schlick(m.color(material, 2), cosOut));
            out.pdf = 0;
            out.lobe = Lobe.SPECULAR_REFLECTION;
            return true;
        }
        if (!(cosOut > 0)) {
            return false;
        }
        double cosHalf = Microfacet.sampleVisibleNormal(s, woX, woY, woZ, cosOut, alpha, u1, u2, out);
        double hx = out.half[0], hy = out.half[1], hz = out.half[2];
        double cosOutHalf = woX * hx + woY * hy + woZ * hz;
        double k = 2 * cosOutHalf;
        out.wiX = k * hx - woX;
        out.wiY = k * hy - woY;
        out.wiZ = k * hz - woZ;
        double cosIn = out.wiX * s.nx + out.wiY * s.ny + out.wiZ * s.nz;
        if (!(cosIn > 0) || !(cosOutHalf > 0)) {
            return false;
        }
        double masking = Microfacet.g2(cosOut, cosIn, alpha) / Microfacet.g1(cosOut, alpha);
        out.setWeight(masking * Optics.schlick(m.color(material, 0), cosOutHalf),
                masking * Optics.schlick(m.color(material, 1), cosOutHalf),
                masking * Optics.schlick(m.color(material, 2), cosOutHalf));
        out.pdf = Microfacet.reflectedPdf(cosOut, cosHalf, alpha);
        out.lobe = Lobe.GLOSSY_REFLECTION;
        return true;
    }

    @Override
    public int lobes(Materials m, int material) {
        return m.parameter(material, ALPHA) < Microfacet.MIRROR_ALPHA ? Lobe.SPECULAR_REFLECTION : Lobe.GLOSSY_REFLECTION;
    }

    /** Sets out's direction to wo mirrored about s's normal. */
    static void mirror(Surface s, double woX, double woY, double woZ, BsdfSample out) {
        double k = 2 * (woX * s.nx + woY * s.ny + woZ * s.nz);
        out.wiX = k * s.nx - woX;
        out.wiY = k * s.ny - woY;
        out.wiZ = k * s.nz - woZ;
    }
}
