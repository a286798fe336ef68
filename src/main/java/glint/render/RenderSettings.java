package glint.render;

import glint.config.Config;
import glint.config.Shading;

/**
 * What the tracer needs to know besides the scene.
 *
 * @param shading      shading model
 * @param recursionMax surface hits along a path (1 = direct light only)
 * @param minWeight    rays whose path weight falls below this are not traced
 * @param epsilon      base of the self-intersection offset, scaled by max(1, |p|)
 * @param glassFresnel how cook-torrance glass splits light between reflection and refraction
 */
public record RenderSettings(Shading shading, int recursionMax, double minWeight, double epsilon,
                             GlassFresnel glassFresnel) {

    /** Glass reflectance: the exact Fresnel equations (the default) or Schlick's approximation. */
    public enum GlassFresnel { EXACT, SCHLICK }

    public RenderSettings(Shading shading, int recursionMax, double minWeight, double epsilon) {
        this(shading, recursionMax, minWeight, epsilon, GlassFresnel.EXACT);
    }

    public static RenderSettings of(Config config) {
        return new RenderSettings(config.shading(), config.recursionMax(), config.minWeight(), config.epsilon());
    }

    public RenderSettings withGlassFresnel(GlassFresnel fresnel) {
        return new RenderSettings(shading, recursionMax, minWeight, epsilon, fresnel);
    }
}
