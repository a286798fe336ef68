package glint.shading;

/**
 * Glass (docs/conventions.md, "cook-torrance"): no light of its own; at its boundary the Fresnel
 * reflectance (exact or Schlick's, 1 past the critical angle) is reflected and the rest refracted,
 * tinted by the material's colour. Smooth below {@link Microfacet#MIRROR_ALPHA} (two delta lobes);
 * otherwise rough (frosted), after Walter et al. 2007, "Microfacet Models for Refraction through Rough
 * Surfaces": GGX normals, each reflecting and refracting by its own Fresnel, height-correlated Smith
 * masking, radiance carried unscaled (no eta^2). Whitted's integrator follows its mirrored and
 * refracted rays alike whatever the roughness ({@link GlassResponse}), and lights a rough one's lobes
 * (its highlight).
 *
 * <p>Throughout, wo is on the side the surface's normal n faces (n.wo > 0), eta = n_o / n_i is the
 * ratio of the index on wo's side to the other's ({@link Optics#eta} of the side met); h is the
 * microfacet normal, facing n: wo + wi normalised for a reflection, eta wo + wi for a refraction.
 */
public final class Dielectric implements Bsdf {

    /** Where its material's ior and GGX alpha stand among its numbers ({@link Materials#parameter}). */
    private static final int IOR = 0, ALPHA = 1;

    /** The numbers glass reads of its material, in order: its ior and GGX alpha ({@link Microfacet#alpha}). */
    public static double[] parameters(double ior, double roughness) {
        return new double[] {ior, Microfacet.alpha(roughness)};
    }

    /** The index of refraction of material {@code material}, a glass. */
    static double ior(Materials m, int material) {
        return m.parameter(material, IOR);
    }

    /** The Fresnel reflectance at cosine cos and ratio eta: exact, or Schlick's where the scene says. */
    static double reflectance(Materials m, double cos, double eta) {
        return m.exactFresnel() ? Optics.fresnelDielectric(cos, eta) : Optics.schlickDielectric(cos, eta);
    }

    /**
     * Whether material {@code material} is rough glass: alpha at least {@link Microfacet#MIRROR_ALPHA},
     * and an ior other than 1 (a boundary of index 1 bends and reflects nothing: light passes straight
     * through, the smooth glass's delta, however rough).
     */
    static boolean rough(Materials m, int material) {
        return m.parameter(material, ALPHA) >= Microfacet.MIRROR_ALPHA && ior(m, material) != 1;
    }

    @Override
    public int lobes(Materials m, int material) {
        return rough(m, material) ? Lobe.GLOSSY_REFLECTION | Lobe.GLOSSY_TRANSMISSION
                : Lobe.SPECULAR_REFLECTION | Lobe.SPECULAR_TRANSMISSION;
    }

    /**
     * Rough glass only (smooth glass has only delta lobes). wi on wo's side: D(h) G2 F(wo.h) / (4 wo.n
     * wi.n); through the surface: D(h) G2 (1 - F(wo.h)) (wo.h) |wi.h| / (wo.n |wi.n| (eta wo.h + wi.h)^2)
     * times the colour; 0 where h would face away from either direction.
     */
    @Override
    public void evaluate(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY,
                         double wiZ, Rgb f) {
        int material = s.material;
        double lobe = roughLobe(m, s, woX, woY, woZ, wiX, wiY, wiZ, false);
        if (wiX * s.nx + wiY * s.ny + wiZ * s.nz > 0) {
            f.set(lobe, lobe, lobe);
        } else {
            f.set(lobe * m.color(material, 0), lobe * m.color(material, 1), lobe * m.color(material, 2));
        }
    }

    /**
     * Rough glass only: a visible normal's density, times the Jacobian of the reflection or the
     * refraction about it, times the chance F or 1 - F that it reflects or refracts.
     */
    @Override
    public double pdf(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY,
                      double wiZ) {
        return roughLobe(m, s, woX, woY, woZ, wiX, wiY, wiZ, true);
    }

    /**
     * What {@link #evaluate} (f before the colour, {@code density} false) or {@link #pdf} ({@code
     * density} true) answers for wi: both from the same microfacet normal h, the half vector of the
     * reflection where wi is on wo's side, of the refraction where it is through the surface; 0 for
     * smooth glass, for wo or wi in the surface, and where h would face away from either direction.
     */
    private static double roughLobe(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY,
                                    double wiZ, boolean density) {
        int material = s.material;
        double cosOut = woX * s.nx + woY * s.ny + woZ * s.nz, cosIn = wiX * s.nx + wiY * s.ny + wiZ * s.nz;
        if (!rough(m, material) || !(cosOut > 0) || !(cosIn != 0)) {
            return 0;
        }
        double alpha = m.parameter(material, ALPHA), eta = Optics.eta(ior(m, material), s.front);
        if (cosIn > 0) {
            double scale = Microfacet.halfScale(woX + wiX, woY + wiY, woZ + wiZ);
            double hx = (woX + wiX) * scale, hy = (woY + wiY) * scale, hz = (woZ + wiZ) * scale;
            double inv = 1 / Math.sqrt(hx * hx + hy * hy + hz * hz);
            double cosHalf = (hx * s.nx + hy * s.ny + hz * s.nz) * inv;
            double cosOutHalf = Math.max(0, (hx * woX + hy * woY + hz * woZ) * inv);
            double reflectance = reflectance(m, cosOutHalf, eta);
            if (density) {
                return reflectance * Microfacet.reflectedPdf(cosOut, cosHalf, alpha);
            }
            // G2 / (4 wo.n wi.n) as one term, as the conductor's
            return Optics.ggx(cosHalf, alpha) * Optics.smithVisibility(cosIn, cosOut, alpha) * reflectance;
        }
        double hx = eta * woX + wiX, hy = eta * woY + wiY, hz = eta * woZ + wiZ;
        double inv = Math.copySign(1 / Math.sqrt(hx * hx + hy * hy + hz * hz), hx * s.nx + hy * s.ny + hz * s.nz);
        hx *= inv;
        hy *= inv;
        hz *= inv;
        double cosOutHalf = hx * woX + hy * woY + hz * woZ, cosInHalf = hx * wiX + hy * wiY + hz * wiZ;
        if (!(cosOutHalf > 0) || !(cosInHalf < 0)) {
            return 0;
        }
        double cosHalf = hx * s.nx + hy * s.ny + hz * s.nz;
        double transmittance = 1 - reflectance(m, cosOutHalf, eta);
        if (density) {
            return transmittance * Microfacet.refractedPdf(cosOut, cosHalf, cosOutHalf, cosInHalf, eta, alpha);
        }
        double denominator = eta * cosOutHalf + cosInHalf;
        return 4 * Optics.smithVisibility(-cosIn, cosOut, alpha) * Optics.ggx(cosHalf, alpha) * transmittance
                * cosOutHalf * -cosInHalf / (denominator * denominator);
    }

    /**
     * Smooth: reflects with probability F (the Fresnel reflectance, 1 past the critical angle), weight
     * 1; otherwise refracts, weight the material's tint: each lobe's factor over its probability.
     * Rough: a normal visible from wo (Heitz 2018), then wo reflected about it with probability F(wo.h),
     * weight G2 / G1(wo), or refracted through it, weight the tint x G2 / G1(wo); false where the
     * direction lands on the wrong side of the surface.
     */
    @Override
    public boolean sample(Materials m, Surface s, double woX, double woY, double woZ, double u1, double u2,
                          double uLobe, BsdfSample out) {
        int material = s.material;
        double eta = Optics.eta(ior(m, material), s.front);
        if (rough(m, material)) {
            return sampleRough(m, s, woX, woY, woZ, eta, u1, u2, uLobe, out);
        }
        double cos = s.cosIncident;
        double reflectance = reflectance(m, cos, eta);
        out.pdf = 0;
        double[] refracted = out.half;
        if (uLobe >= reflectance && Optics.refract(-woX, -woY, -woZ, s.nx, s.ny, s.nz, cos, eta, refracted)) {
            out.wiX = refracted[0];
            out.wiY = refracted[1];
            out.wiZ = refracted[2];
            out.setWeight(m.color(material, 0), m.color(material, 1), m.color(material, 2));
            out.lobe = Lobe.SPECULAR_TRANSMISSION;
            return true;
        }
        Conductor.mirror(s, woX, woY, woZ, out);
        out.setWeight(1, 1, 1);
        out.lobe = Lobe.SPECULAR_REFLECTION;
        return true;
    }

    private static boolean sampleRough(Materials m, Surface s, double woX, double woY, double woZ, double eta,
                                       double u1, double u2, double uLobe, BsdfSample out) {
        int material = s.material;
        double alpha = m.parameter(material, ALPHA);
        double cosOut = woX * s.nx + woY * s.ny + woZ * s.nz;
        if (!(cosOut > 0)) {
            return false;
        }
        double cosHalf = Microfacet.sampleVisibleNormal(s, woX, woY, woZ, cosOut, alpha, u1, u2, out);
        double hx = out.half[0], hy = out.half[1], hz = out.half[2];
        double cosOutHalf = woX * hx + woY * hy + woZ * hz;
        if (!(cosOutHalf > 0)) {
            return false;
        }
        double reflectance = reflectance(m, cosOutHalf, eta);
        if (uLobe < reflectance) {
            double k = 2 * cosOutHalf;
            out.wiX = k * hx - woX;
            out.wiY = k * hy - woY;
            out.wiZ = k * hz - woZ;
            double cosIn = out.wiX * s.nx + out.wiY * s.ny + out.wiZ * s.nz;
            if (!(cosIn > 0)) {
                return false;
            }
            double masking = Microfacet.g2(cosOut, cosIn, alpha) / Microfacet.g1(cosOut, alpha);
            out.setWeight(masking, masking, masking);
            out.pdf = reflectance * Microfacet.reflectedPdf(cosOut, cosHalf, alpha);
            out.lobe = Lobe.GLOSSY_REFLECTION;
            return true;
        }
        double bend = Optics.refractionBend(cosOutHalf, eta);
        if (Double.isNaN(bend)) { // past the critical angle F is 1: not reached
            return false;
        }
        double[] refracted = out.half;
        Optics.refractWithBend(-woX, -woY, -woZ, hx, hy, hz, eta, bend, refracted);
        out.wiX = refracted[0];
        out.wiY = refracted[1];
        out.wiZ = refracted[2];
        double cosIn = out.wiX * s.nx + out.wiY * s.ny + out.wiZ * s.nz;
        double cosInHalf = out.wiX * hx + out.wiY * hy + out.wiZ * hz;
        if (!(cosIn < 0)) {
            return false;
        }
        double masking = Microfacet.g2(cosOut, -cosIn, alpha) / Microfacet.g1(cosOut, alpha);
        out.setWeight(masking * m.color(material, 0), masking * m.color(material, 1), masking * m.color(material, 2));
        out.pdf = (1 - reflectance) * Microfacet.refractedPdf(cosOut, cosHalf, cosOutHalf, cosInHalf, eta, alpha);
        out.lobe = Lobe.GLOSSY_TRANSMISSION;
        return true;
    }
}
