package glint.shading;

/**
 * The physically based model (SPEC section 4): each material type scatters light by its own
 * {@link Bsdf} (Lambert matte, conductor metal, dielectric glass). Shadows are hard; glass blocks
 * light.
 */
public final class CookTorrance implements ShadingModel {

    @Override
    public void shade(ShadingContext c, PathVertex v, double dx, double dy, double dz, int hitsLeft, double weight) {
        Bsdf bsdf = c.materials().bsdf(v.surface.material);
        bsdf.direct(c, v, dx, dy, dz);
        bsdf.scatter(c, v, dx, dy, dz, hitsLeft, weight);
        v.radiance.set(v.sum.r, v.sum.g, v.sum.b);
    }

    @Override
    public void direct(ShadingContext c, PathVertex v, double dx, double dy, double dz) {
        c.materials().bsdf(v.surface.material).direct(c, v, dx, dy, dz);
    }

    @Override
    public void boundary(ShadingContext c, PathVertex v) {
        c.materials().bsdf(v.surface.material).boundary(c, v);
    }
}
