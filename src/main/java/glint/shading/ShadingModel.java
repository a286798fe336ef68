package glint.shading;

/**
 * A shading model: the radiance a surface sends back along a ray. A surface's radiance is its own
 * light ({@link #direct}) plus what its reflected and refracted rays bring back; a material that
 * refracts states its boundary's factors ({@link #boundary}), and
 * {@link ShadingContext#scatter} traces both rays for every model alike.
 */
public interface ShadingModel {

    /**
     * Shades vertex {@code v} (its surface filled in) of a ray along unit d into
     * {@code v.radiance}: {@code hitsLeft} surface hits the path may still shade (this one
     * included), {@code weight} the path's throughput so far.
     */
    void shade(ShadingContext c, PathVertex v, double dx, double dy, double dz, int hitsLeft, double weight);

    /**
     * The light v's surface sends back along the ray of unit direction d by itself (ambient and
     * the lights it sees), into {@code v.sum}.
     */
    void direct(ShadingContext c, PathVertex v, double dx, double dy, double dz);

    /**
     * The factors of v's surface as a refracting boundary, into {@code v.eta}, {@code v.reflect} and
     * {@code v.transmitR/G/B}: they depend on the material, the side met and the cosine alone.
     */
    void boundary(ShadingContext c, PathVertex v);
}
