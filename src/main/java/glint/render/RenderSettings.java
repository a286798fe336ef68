package glint.render;

/**
 * What the tracer needs to know besides the scene.
 *
 * @param shading      shading model
 * @param recursionMax surface hits along a path (1 = direct light only)
 * @param minWeight    the path weight below which a ray is pruned (0: none is)
 * @param epsilon      base of the self-intersection offset, scaled by max(1, |p|)
 * @param glassFresnel how cook-torrance glass splits light between reflection and refraction
 * @param pruning      what happens to a ray whose path weight falls below {@code minWeight}
 * @param transport    the integrator: Whitted's, the path tracer or the bidirectional one
 * @param merging      whether the bidirectional integrator also merges camera vertices with light
 *                     subpaths' (the default; without, it is unbiased and blind to light focused by
 *                     glass and then seen through glass or in a mirror)
 */
public record RenderSettings(Shading shading, int recursionMax, double minWeight, double epsilon,
                             GlassFresnel glassFresnel, Pruning pruning, LightTransport transport, boolean merging) {

    /** Glass reflectance: the exact Fresnel equations (the default) or Schlick's approximation. */
    public enum GlassFresnel { EXACT, SCHLICK }

    /**
     * What becomes of a ray whose path weight w falls below min_weight. {@link #ROULETTE} (the
     * default): it is traced with probability w / min_weight and its light divided by that
     * probability, so the expected image is the unpruned one. {@link #CUTOFF}: it is not traced
     * and brings black, a loss that grows with min_weight.
     */
    public enum Pruning { ROULETTE, CUTOFF }

    public RenderSettings(Shading shading, int recursionMax, double minWeight, double epsilon) {
        this(shading, recursionMax, minWeight, epsilon, GlassFresnel.EXACT, Pruning.ROULETTE, LightTransport.WHITTED,
                true);
    }

    public RenderSettings withGlassFresnel(GlassFresnel fresnel) {
        return new RenderSettings(shading, recursionMax, minWeight, epsilon, fresnel, pruning, transport, merging);
    }

    public RenderSettings withPruning(Pruning mode) {
        return new RenderSettings(shading, recursionMax, minWeight, epsilon, glassFresnel, mode, transport, merging);
    }

    public RenderSettings withTransport(LightTransport integrator) {
        return new RenderSettings(shading, recursionMax, minWeight, epsilon, glassFresnel, pruning, integrator, merging);
    }

    public RenderSettings withMerging(boolean merges) {
        return new RenderSettings(shading, recursionMax, minWeight, epsilon, glassFresnel, pruning, transport, merges);
    }
}
