package glint.shading;

/**
 * A shading model of Whitted's integrator: the light a surface sends back by itself
 * ({@link #direct}), and the single rays it sends on ({@link #specular}), which the integrator
 * traces for every model alike.
 */
public interface ShadingModel {

    /**
     * The light v's surface (filled in) sends back along the ray of unit direction d by itself
     * (its own light, ambient and the lights it sees), into {@code v.sum}.
     */
    void direct(ShadingContext c, PathVertex v, double dx, double dy, double dz);

    /**
     * The factors of the rays v's surface sends on, into {@code v.reflectR/G/B}, {@code v.eta} and
     * {@code v.transmitR/G/B}: they depend on the material, the side met and the cosine alone.
     */
    void specular(ShadingContext c, PathVertex v);
}
