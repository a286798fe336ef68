package glint.shading;

/**
 * The light loop both integrators share: what every light sends from a surface towards wo through
 * its BSDF, f(wo, wi) x the light's irradiance x n.wi x the fraction its shadow ray passes.
 */
public final class DirectLight {

    private DirectLight() {
    }

    /**
     * The sum over {@code lights} seen from s through {@code bsdf}, into {@code out}; {@code light} and
     * {@code f} are scratch values.
     */
    public static void sum(LightQuery rays, Lights lights, Materials m, Bsdf bsdf, Surface s, double woX,
                           double woY, double woZ, LightSample light, Rgb f, Rgb out) {
        double r = 0, g = 0, b = 0;
        for (int i = 0, n = lights.count(); i < n; i++) {
            double pass = rays.lightReaching(s, i, light);
            if (pass > 0) {
                bsdf.evaluate(m, s, woX, woY, woZ, light.dirX, light.dirY, light.dirZ, f);
                double k = pass * light.cosine;
                r += f.r * light.irradianceR * k;
                g += f.g * light.irradianceG * k;
                b += f.b * light.irradianceB * k;
            }
        }
        out.set(r, g, b);
    }
}
