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
}
