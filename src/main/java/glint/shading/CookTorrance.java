package glint.shading;

/**
 * The physically based model (docs/conventions.md, "cook-torrance") in Whitted's integrator: each
 * material scatters light by its own {@link Bsdf}. A surface sends back its own light, ambient x its
 * albedo where ambient reaches it, and the lights it sees through its lobes that are not delta; it
 * sends on the single rays of its {@link WhittedResponse}. Shadows are hard; glass blocks light.
 */
public final class CookTorrance implements ShadingModel {

    @Override
    public void direct(ShadingContext c, Surface s, double dx, double dy, double dz, LightSample light, Rgb f,
                       Rgb sum) {
        Materials m = c.materials();
        int material = s.material;
        Bsdf bsdf = m.bsdf(material);
        if (m.isDelta(material)) {
            sum.set(0, 0, 0);
        } else {
            DirectLight.sum(c, c.lights(), m, bsdf, s, -dx, -dy, -dz, false, light, f, sum);
        }
        if (m.ambientLit(material)) {
            sum.r += c.ambient(0) * m.color(material, 0);
            sum.g += c.ambient(1) * m.color(material, 1);
            sum.b += c.ambient(2) * m.color(material, 2);
        }
        if (m.emits(material)) {
            bsdf.emitted(m, s, f);
            sum.r += f.r;
            sum.g += f.g;
            sum.b += f.b;
        }
    }

    @Override
    public void specular(ShadingContext c, Surface s, SingleRays out) {
        Materials m = c.materials();
        m.response(s.material).specular(m, s, out);
    }
}
