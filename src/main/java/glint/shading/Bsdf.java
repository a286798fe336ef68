package glint.shading;

/**
 * How one material type scatters light (pbrt's BxDF, Mitsuba's BSDF): f(wo, wi) ({@link #evaluate}),
 * a direction sampled with its weight and density ({@link #sample}, {@link #pdf}), the kinds of its
 * lobes ({@link #lobes}) and its own light ({@link #emitted}). It only answers: the integrators own
 * the light loop, the depth and the rays. One per material type ({@code glint.registry.MaterialType}):
 * {@link Lambert}, {@link Conductor}, {@link Dielectric}; what Whitted's models ask besides is the
 * type's {@link WhittedResponse}.
 */
public interface Bsdf {

    // wo and wi are unit world directions away from surface s (wo towards where the light goes, the
    // reverse of the incoming ray), s's normal faces wo; the material is s.material.

    /**
     * f(wo, wi) of the material's lobes that are not delta, per channel, into {@code f} (0 where none),
     * for wi anywhere on the sphere: on wo's side its reflection, through the surface its transmission.
     */
    void evaluate(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY, double wiZ,
                  Rgb f);

    /** The density per solid angle with which {@link #sample} picks wi; 0 for a delta lobe's. */
    double pdf(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY, double wiZ);

    /**
     * Samples a direction wi for wo from the uniform numbers u1, u2 (the direction) and uLobe (which
     * lobe), into {@code out}: wi, the weight f |cos| / pdf, the pdf and the kind of lobe that chose it.
     * False where no direction is sampled (it would point into the surface): the path ends.
     */
    boolean sample(Materials m, Surface s, double woX, double woY, double woZ, double u1, double u2, double uLobe,
                   BsdfSample out);

    /**
     * The kinds of material {@code material}'s lobes, {@link Lobe}'s bits: all of them delta (or none)
     * means no light sample sees it ({@link Materials#isDelta}). Asked once per material.
     */
    int lobes(Materials m, int material);

    /** Whether the surface sends light of its own ({@link #emitted}). */
    default boolean emits() {
        return false;
    }

    /** The radiance the surface sends of its own towards wo, into {@code out}, where it {@link #emits}. */
    default void emitted(Materials m, Surface s, Rgb out) {
        out.set(0, 0, 0);
    }
}
