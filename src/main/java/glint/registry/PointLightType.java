package glint.registry;

import glint.scene.Light;
import glint.shading.PointLightSampler;
import java.util.List;

/**
 * {@code {type: point, position: [x, y, z]}}: a {@link Light.Point}, its position kept, sampled by
 * {@link PointLightSampler}; all its light leaves one point.
 */
public final class PointLightType {

    public static final LightType<Light.Point> TYPE = new LightType<>("point", Light.Point.class, List.of("position"),
            (fields, color, intensity) -> new Light.Point(fields.vector("position"), color, intensity),
            Light.Point::position, new PointLightSampler(), true);

    private PointLightType() {
    }
}
