package glint.shading;

/**
 * A shading model of Whitted's integrator: the light a surface sends back by itself
 * ({@link #direct}), and the single rays it sends on ({@link #specular}), which the integrator
 * traces for every model alike.
 */
public interface ShadingModel {

    /**
     * The light surface s sends back along the ray of unit direction d by itself (its own light,
     * ambient and the lights it sees), into {@code sum}; {@code light} and {@code f} are scratch values.
     */
    void direct(ShadingContext c, Surface s, double dx, double dy, double dz, LightSample light, Rgb f, Rgb sum);

    /**
     * The factors of the rays surface s sends on, into {@code out}: they depend on the material, the
     * side met and the cosine alone.
     */
    void specular(ShadingContext c, Surface s, SingleRays out);
}
