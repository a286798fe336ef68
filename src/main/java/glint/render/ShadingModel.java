package glint.render;

/** A shading model: the radiance a surface sends back along a ray, from the materials' functions. */
interface ShadingModel {

    /**
     * Shades vertex {@code v} (its surface filled in) of a ray along unit d into
     * {@code v.radiance}: {@code hitsLeft} surface hits the path may still shade (this one
     * included), {@code weight} the path's throughput so far.
     */
    void shade(Integrator integrator, PathVertex v, double dx, double dy, double dz, int hitsLeft, double weight);
}
