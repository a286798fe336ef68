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

    /** Whether light passes through the material (the phong model's shadow rays pass kt of it). */
    default boolean transmits() {
        return false;
    }
}
