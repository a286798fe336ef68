package glint.shading;

/**
 * The physically based model (SPEC section 4) in Whitted's integrator: each material scatters light
 * by its own {@link Bsdf}. A surface sends back its own light, ambient x its albedo where ambient
 * reaches it, and the lights it sees through its lobes that are not delta; it sends on the single rays
 * of {@link Bsdf#specular}. Shadows are hard; glass blocks light.
 */
public final class CookTorrance implements ShadingModel {

    @Override
    public void direct(ShadingContext c, PathVertex v, double dx, double dy, double dz) {
        Surface s = v.surface;
        Materials m = c.materials();
        int material = s.material;
        Bsdf bsdf = m.bsdf(material);
        Rgb sum = v.sum;
        if (m.isDelta(material)) {
            sum.set(0, 0, 0);
        } else {
            DirectLight.sum(c, c.lights(), m, bsdf, s, -dx, -dy, -dz, v.light, v.f, sum);
        }
        if (m.ambientLit(material)) {
            sum.r += c.ambient(0) * m.color(material, 0);
            sum.g += c.ambient(1) * m.color(material, 1);
            sum.b += c.ambient(2) * m.color(material, 2);
        }
        if (m.emits(material)) {
            bsdf.emitted(m, s, v.f);
            sum.r += v.f.r;
            sum.g += v.f.g;
            sum.b += v.f.b;
        }
    }

    @Override
    public void specular(ShadingContext c, PathVertex v) {
        Materials m = c.materials();
        m.bsdf(v.surface.material).specular(m, v.surface, v);
    }
}
