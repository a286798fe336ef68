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
 */
public record RenderSettings(Shading shading, int recursionMax, double minWeight, double epsilon) {

    public static RenderSettings of(Config config) {
        return new RenderSettings(config.shading(), config.recursionMax(), config.minWeight(), config.epsilon());
    }
}
