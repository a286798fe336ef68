package glint.shading;

/**
 * A smooth glass: no light of its own; at its boundary the Fresnel reflectance (exact or Schlick's,
 * 1 past the critical angle) is reflected and the rest refracted, tinted by the material's colour.
 */
public final class Dielectric implements Bsdf {

    @Override
    public void specular(Materials m, Surface s, SingleRays out) {
        int material = s.material;
        out.eta = Optics.eta(m.ior(material), s.front);
        double reflectance = reflectance(m, s.cosIncident, out.eta);
        out.setReflect(reflectance, reflectance, reflectance);
        out.setTransmit((1 - reflectance) * m.color(material, 0), (1 - reflectance) * m.color(material, 1),
                (1 - reflectance) * m.color(material, 2));
    }

    /** The Fresnel reflectance at cosine cos and ratio eta: exact, or Schlick's where the scene says. */
    private static double reflectance(Materials m, double cos, double eta) {
        return m.exactFresnel() ? Optics.fresnelDielectric(cos, eta) : Optics.schlickDielectric(cos, eta);
    }

    @Override
    public boolean transmits() {
        return true;
    }

    /** Smooth glass has only delta lobes. */
    @Override
    public void evaluate(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY,
                         double wiZ, Rgb f) {
        f.set(0, 0, 0);
    }

    @Override
    public double pdf(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY,
                      double wiZ) {
        return 0;
    }

    /**
     * Reflects with probability F (the Fresnel reflectance, 1 past the critical angle), weight 1;
     * otherwise refracts, weight the material's tint: each lobe's factor over its probability.
     */
    @Override
    public boolean sample(Materials m, Surface s, double woX, double woY, double woZ, double u1, double u2,
                          double uLobe, BsdfSample out) {
        int material = s.material;
        double eta = Optics.eta(m.ior(material), s.front);
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

    @Override
    public int lobes(Materials m, int material) {
        return Lobe.SPECULAR_REFLECTION | Lobe.SPECULAR_TRANSMISSION;
    }
}
