package glint.registry;

import glint.scene.Light;
import glint.shading.DirectionalLightSampler;
import java.util.List;

/**
 * {@code {type: directional, direction: [x, y, z]}}: a {@link Light.Directional}, the direction
 * towards it kept, sampled by {@link DirectionalLightSampler}.
 */
public final class DirectionalLightType {

    public static final LightType<Light.Directional> TYPE = new LightType<>("directional", Light.Directional.class,
            List.of("direction"),
            (fields, color, intensity) -> new Light.Directional(fields.direction("direction"), color, intensity),
            light -> light.direction().scale(-1), new DirectionalLightSampler(), false);

    private DirectionalLightType() {
    }
}
