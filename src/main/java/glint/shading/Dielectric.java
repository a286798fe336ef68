package glint.shading;

/**
 * A smooth glass: no light of its own; at its boundary the Fresnel reflectance (exact or Schlick's,
 * 1 past the critical angle) is reflected and the rest refracted, tinted by the material's colour.
 */
public final class Dielectric implements Bsdf {

    @Override
    public void direct(ShadingContext c, PathVertex v, double dx, double dy, double dz) {
        v.sum.set(0, 0, 0);
    }

    @Override
    public void scatter(ShadingContext c, PathVertex v, double dx, double dy, double dz, int hitsLeft, double weight) {
        boundary(c, v);
        c.scatter(v, dx, dy, dz, hitsLeft, weight);
    }

    @Override
    public void boundary(ShadingContext c, PathVertex v) {
        Surface s = v.surface;
        Materials m = c.materials();
        int material = s.material;
        v.eta = Optics.eta(m.ior(material), s.front);
        double reflectance = c.exactFresnel() ? Optics.fresnelDielectric(s.cosIncident, v.eta)
                : Optics.schlickDielectric(s.cosIncident, v.eta);
        v.reflect = reflectance;
        v.transmitR = (1 - reflectance) * m.color(material, 0);
        v.transmitG = (1 - reflectance) * m.color(material, 1);
        v.transmitB = (1 - reflectance) * m.color(material, 2);
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
        double reflectance = m.exactFresnel() ? Optics.fresnelDielectric(cos, eta) : Optics.schlickDielectric(cos, eta);
        out.pdf = 0;
        out.delta = true;
        double[] refracted = out.half;
        if (uLobe >= reflectance && Optics.refract(-woX, -woY, -woZ, s.nx, s.ny, s.nz, cos, eta, refracted)) {
            out.wiX = refracted[0];
            out.wiY = refracted[1];
            out.wiZ = refracted[2];
            out.setWeight(m.color(material, 0), m.color(material, 1), m.color(material, 2));
            out.transmitted = true;
            return true;
        }
        Conductor.mirror(s, woX, woY, woZ, out);
        out.setWeight(1, 1, 1);
        out.transmitted = false;
        return true;
    }

    @Override
    public boolean isDelta(Materials m, int material) {
        return true;
    }
}
