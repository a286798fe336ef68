package glint.recipe;

import glint.math.Vector3d;
import glint.registry.LightType;
import glint.shading.Lights;
import java.util.List;

/**
 * The registration of the lamp: {@code {type: lamp, position: [x, y, z]}}, a {@link Lamp}, compiled to
 * its position and power, sampled by {@link LampSampler}; all its light leaves one point.
 */
final class LampType {

    static final LightType<Lamp> TYPE = new LightType<>("lamp", Lamp.class, List.of("position"),
            (fields, color, intensity) -> new Lamp(fields.vector("position"), color, intensity), LampType::compile);

    private LampType() {
    }

    private static LightType.Compiled compile(Lamp lamp) {
        Vector3d p = lamp.position();
        Vector3d power = lamp.color().scale(lamp.intensity());
        return new LightType.Compiled(new Lights.Light(new LampSampler(),
                new double[] {p.x(), p.y(), p.z(), power.x(), power.y(), power.z()}, p));
    }
}
