package glint.recipe;

import glint.registry.LightType;
import java.util.List;

/**
 * The registration of the lamp: {@code {type: lamp, position: [x, y, z]}}, a {@link Lamp}, its
 * position kept, sampled by {@link LampSampler}; all its light leaves one point.
 */
final class LampType {

    static final LightType<Lamp> TYPE = new LightType<>("lamp", Lamp.class, List.of("position"),
            (fields, color, intensity) -> new Lamp(fields.vector("position"), color, intensity), Lamp::position,
            new LampSampler(), true);

    private LampType() {
    }
}
