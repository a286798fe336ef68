package glint.shading;

/** A matte surface: Lambert's term, albedo / pi x the irradiance from each light it sees, plus ambient x albedo. */
public final class Lambert implements Bsdf {

    private static final double INV_PI = 1 / Math.PI;

    @Override
    public void direct(ShadingContext c, PathVertex v, double dx, double dy, double dz) {
        Surface s = v.surface;
        LightSample light = v.light;
        Lights lights = c.lights();
        double irradianceR = 0, irradianceG = 0, irradianceB = 0;
        for (int i = 0; i < lights.count(); i++) {
            if (c.lightReaching(s, i, light) > 0) {
                irradianceR += light.irradianceR * light.cosine;
                irradianceG += light.irradianceG * light.cosine;
                irradianceB += light.irradianceB * light.cosine;
            }
        }
        Materials m = c.materials();
        int material = s.material;
        v.sum.set(radiance(m.color(material, 0), irradianceR, c.ambient(0)),
                radiance(m.color(material, 1), irradianceG, c.ambient(1)),
                radiance(m.color(material, 2), irradianceB, c.ambient(2)));
    }

    /** A matte surface sends no rays on. */
    @Override
    public void scatter(ShadingContext c, PathVertex v, double dx, double dy, double dz, int hitsLeft, double weight) {
    }

    /** One channel: albedo / pi x the irradiance summed over the lights it sees (n.l applied), plus ambient x albedo. */
    static double radiance(double albedo, double irradiance, double ambient) {
        return albedo * (irradiance * INV_PI + ambient);
    }
}
