package glint.registry;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.scene.Light;
import glint.shading.DirectionalLightSampler;
import glint.shading.Lights;
import glint.shading.SunSampler;
import java.util.List;

/**
 * {@code {type: directional, direction: [x, y, z], angle: a}}: a {@link Light.Directional}. Of angle 0
 * (the default) sampled by {@link DirectionalLightSampler}, the same direction everywhere; of an
 * angle above 0 (degrees, the disc's apparent diameter; the sun's is 0.53) a sun, sampled over its
 * disc by {@link SunSampler}.
 */
public final class DirectionalLightType {

    /**
     * The smallest angle of a sun, in degrees: its disc's radiance, colour x intensity / (pi sin^2),
     * stays finite far below it. A narrower disc is written as 0.
     */
    static final double SMALLEST_ANGLE = 1e-9;

    public static final LightType<Light.Directional> TYPE = new LightType<>("directional", Light.Directional.class,
            List.of("direction", "angle"), DirectionalLightType::read, DirectionalLightType::compile);

    private DirectionalLightType() {
    }

    private static Light.Directional read(Fields fields, Vector3d color, double intensity) throws InputException {
        Vector3d direction = fields.direction("direction");
        double angle = 0;
        if (fields.has("angle")) {
            angle = fields.number("angle");
            if (!(angle >= 0 && angle < 180)) {
                throw fields.error("angle", "angle must lie in [0, 180) degrees (the disc's apparent diameter; the"
                        + " sun's is 0.53), got " + fields.written("angle"));
            }
            if (angle > 0 && angle < SMALLEST_ANGLE) {
                throw fields.error("angle", "angle must be 0 (no size) or at least 1e-9 degrees, got "
                        + fields.written("angle"));
            }
        }
        return new Light.Directional(direction, color, intensity, angle);
    }

    private static LightType.Compiled compile(Light.Directional light) {
        Vector3d towards = light.direction().scale(-1);
        Vector3d irradiance = light.color().scale(light.intensity());
        if (light.angleDegrees() == 0) {
            return new LightType.Compiled(new Lights.Light(new DirectionalLightSampler(),
                    DirectionalLightSampler.data(towards.x(), towards.y(), towards.z(), irradiance.x(), irradiance.y(),
                            irradiance.z()), null));
        }
        double radius = Math.toRadians(light.angleDegrees()) / 2;
        return new LightType.Compiled(new Lights.Light(new SunSampler(),
                SunSampler.data(towards.x(), towards.y(), towards.z(), radius, irradiance.x(), irradiance.y(),
                        irradiance.z()), null));
    }
}
