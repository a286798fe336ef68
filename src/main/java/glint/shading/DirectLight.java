package glint.shading;

/**
 * The light loop both integrators share: what every light sends from a surface towards wo through
 * its BSDF, f(wo, wi) x the irradiance the light's sample stands for x |n.wi| x the fraction its
 * shadow ray passes (a light behind the surface reaches it where a lobe sends light through it), weighed against the BSDF's own sampling of the light where the caller asks
 * ({@link Mis}).
 */
public final class DirectLight {

    private DirectLight() {
    }

    /**
     * The sum over {@code lights} seen from s through {@code bsdf}, into {@code out}; {@code light} and
     * {@code f} are scratch values. With {@code weighed}, the sample of a light that a BSDF sample can
     * meet too (not a delta light) counts by the power heuristic against the BSDF's density.
     */
    public static void sum(LightQuery rays, Lights lights, Materials m, Bsdf bsdf, Surface s, double woX,
                           double woY, double woZ, boolean weighed, LightSample light, Rgb f, Rgb out) {
        double r = 0, g = 0, b = 0;
        boolean through = Lobe.transmitsNonDelta(m.lobes(s.material));
        for (int i = 0, n = lights.count(); i < n; i++) {
            double pass = rays.lightReaching(s, i, through, light);
            if (pass > 0) {
                bsdf.evaluate(m, s, woX, woY, woZ, light.dirX, light.dirY, light.dirZ, f);
                double k = pass * light.cosine;
                if (weighed && light.pdf > 0) {
                    k *= Mis.powerHeuristic(light.pdf,
                            bsdf.pdf(m, s, woX, woY, woZ, light.dirX, light.dirY, light.dirZ));
                }
                r += f.r * light.irradianceR * k;
                g += f.g * light.irradianceG * k;
                b += f.b * light.irradianceB * k;
            }
        }
        out.set(r, g, b);
    }
}
