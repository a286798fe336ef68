package glint.shading;

/**
 * What Whitted's shading models ask of a material type besides its {@link Bsdf}: the single rays it is
 * followed along in place of its lobes ({@link #specular}), whether Whitted's ambient light reaches it
 * ({@link #ambientLit}), and whether the phong model's shadow rays pass through it ({@link #transmits}).
 * Each material type registers one beside its BSDF ({@code glint.registry.MaterialType}):
 * {@link MatteResponse}, {@link MetalResponse}, {@link GlassResponse}. The path integrator never asks it.
 */
public interface WhittedResponse {

    /**
     * The factors of the single rays the surface sends on in place of its lobes, into {@code out}: the
     * mirrored ray's per channel (a glossy lobe is followed along its mirror direction) and, for one that
     * refracts, eta and the tint of the refracted ray (0 for none). They depend on the material, the side
     * met and the cosine alone.
     */
    void specular(Materials m, Surface s, SingleRays out);

    /** Whether Whitted's ambient light reaches the surface, times its colour (a matte surface's albedo). */
    default boolean ambientLit() {
        return false;
    }

    /** Whether the phong model's reflection and highlight take the material's colour (a metal's do). */
    default boolean tintsReflection() {
        return false;
    }

    /** Whether light passes through the material (the phong model's shadow rays pass kt of it). */
    default boolean transmits() {
        return false;
    }
}
