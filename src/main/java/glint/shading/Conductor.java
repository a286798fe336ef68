package glint.shading;

/**
 * A metal: a mirror weighted by Schlick's Fresnel with F0 = the material's colour, plus, when it is
 * rough, a GGX highlight from each light it sees.
 */
public final class Conductor implements Bsdf {

    /** The GGX highlight from each light the surface sees, when rough. */
    @Override
    public void direct(ShadingContext c, PathVertex v, double dx, double dy, double dz) {
        Surface s = v.surface;
        Materials m = c.materials();
        int material = s.material;
        Rgb sum = v.sum;
        sum.set(0, 0, 0);
        if (m.alpha(material) > 0 && s.cosIncident > 0) {
            LightSample light = v.light;
            Lights lights = c.lights();
            for (int i = 0; i < lights.count(); i++) {
                if (c.lightReaching(s, i, light) > 0) {
                    addHighlight(m, material, s, light, dx, dy, dz, sum);
                }
            }
        }
    }

    /** The mirrored ray, weighted by Schlick's Fresnel per channel. */
    @Override
    public void scatter(ShadingContext c, PathVertex v, double dx, double dy, double dz, int hitsLeft, double weight) {
        if (hitsLeft <= 1) {
            return;
        }
        Surface s = v.surface;
        Materials m = c.materials();
        int material = s.material;
        c.addReflected(s, dx, dy, dz, hitsLeft, weight, Optics.schlick(m.color(material, 0), s.cosIncident),
                Optics.schlick(m.color(material, 1), s.cosIncident),
                Optics.schlick(m.color(material, 2), s.cosIncident), v.sum);
    }

    /**
     * Adds the GGX highlight from one light to {@code sum}: D(h) V(l, v) n.l x F(v.h) x the light's
     * irradiance, F Schlick's with F0 = the material's colour. The view direction is -d; the
     * sample's direction is the unit direction to the light, its cosine n.l > 0.
     */
    private static void addHighlight(Materials materials, int m, Surface s, LightSample l, double dx, double dy,
                                     double dz, Rgb sum) {
        double alpha = materials.alpha(m);
        double cosLight = l.cosine;
        double hx = l.dirX - dx, hy = l.dirY - dy, hz = l.dirZ - dz;
        double inv = 1 / Math.sqrt(hx * hx + hy * hy + hz * hz);
        double cosHalf = (hx * s.nx + hy * s.ny + hz * s.nz) * inv;
        double cosViewHalf = Math.max(0, -(hx * dx + hy * dy + hz * dz) * inv);
        double specular = Optics.ggx(cosHalf, alpha) * Optics.smithVisibility(cosLight, s.cosIncident, alpha) * cosLight;
        sum.r += specular * Optics.schlick(materials.color(m, 0), cosViewHalf) * l.irradianceR;
        sum.g += specular * Optics.schlick(materials.color(m, 1), cosViewHalf) * l.irradianceG;
        sum.b += specular * Optics.schlick(materials.color(m, 2), cosViewHalf) * l.irradianceB;
    }
}
