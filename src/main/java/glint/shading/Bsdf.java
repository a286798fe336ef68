package glint.shading;

/**
 * How one material type scatters light in the physically based model ({@link CookTorrance}): the
 * light its surface sends back by itself, and the rays it sends on. One per material type
 * ({@code glint.scene.MaterialType}); {@link Lambert}, {@link Conductor} and {@link Dielectric}.
 */
public interface Bsdf {

    /**
     * The light v's surface sends back along the ray of unit direction d by itself (ambient and the
     * lights it sees), into {@code v.sum}.
     */
    void direct(ShadingContext c, PathVertex v, double dx, double dy, double dz);

    /**
     * Adds to {@code v.sum} what the rays the surface sends on bring back: {@code hitsLeft} hits the
     * path may still shade (this one included), {@code weight} its throughput so far.
     */
    void scatter(ShadingContext c, PathVertex v, double dx, double dy, double dz, int hitsLeft, double weight);

    /**
     * For a material that refracts, its boundary's factors into {@code v.eta}, {@code v.reflect}
     * and {@code v.transmitR/G/B}; the others have none.
     */
    default void boundary(ShadingContext c, PathVertex v) {
    }

    // ------------------------------------------------------------ the BSDF as a function of directions
    // wo and wi are unit world directions away from surface s (wo towards where the light goes, the
    // reverse of the incoming ray), s's normal faces wo; the material is s.material.

    /** f(wo, wi) of the material's lobes that are not delta, per channel, into {@code f} (0 where none). */
    void evaluate(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY, double wiZ,
                  Rgb f);

    /** The density per solid angle with which {@link #sample} picks wi; 0 for a delta lobe's. */
    double pdf(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY, double wiZ);

    /**
     * Samples a direction wi for wo from the uniform numbers u1, u2 (the direction) and uLobe (which
     * lobe), into {@code out}: wi, the weight f cos / pdf, the pdf and whether a delta lobe chose it.
     * False where no direction is sampled (it would point into the surface): the path ends.
     */
    boolean sample(Materials m, Surface s, double woX, double woY, double woZ, double u1, double u2, double uLobe,
                   BsdfSample out);

    /** Whether every lobe of material {@code material} is a delta (a mirror, smooth glass): no light sample sees it. */
    boolean isDelta(Materials m, int material);

    /** Whether light passes through the material (the phong model's shadow rays pass kt of it). */
    default boolean transmits() {
        return false;
    }
}
