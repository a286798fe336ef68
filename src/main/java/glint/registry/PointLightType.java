package glint.registry;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.scene.Light;
import glint.scene.Sphere;
import glint.shading.Lights;
import glint.shading.PointLightSampler;
import glint.shading.SphereLightSampler;
import java.util.List;

/**
 * {@code {type: point, position: [x, y, z], radius: r}}: a {@link Light.Point}. Of radius 0 (the
 * default) a point light, sampled by {@link PointLightSampler}, all its light leaving one point; of a
 * radius above 0 a sphere light, sampled by {@link SphereLightSampler}, whose sphere rays meet.
 */
public final class PointLightType {

    /** The smallest and largest radius of a sphere light: its radiance, colour x intensity / (pi r^2), stays finite. */
    static final double SMALLEST_RADIUS = 1e-50, LARGEST_RADIUS = 1e50;

    public static final LightType<Light.Point> TYPE = new LightType<>("point", Light.Point.class,
            List.of("position", "radius"), PointLightType::read, PointLightType::compile);

    private PointLightType() {
    }

    private static Light.Point read(Fields fields, Vector3d color, double intensity) throws InputException {
        Vector3d position = fields.vector("position");
        double radius = 0;
        if (fields.has("radius")) {
            radius = fields.number("radius");
            if (radius < 0) {
                throw fields.error("radius", "radius must be >= 0 (0 is a point light), got "
                        + fields.written("radius"));
            }
            if (radius > 0 && (radius < SMALLEST_RADIUS || radius > LARGEST_RADIUS)) {
                throw fields.error("radius", "radius must be 0 (a point light) or between 1e-50 and 1e50, got "
                        + fields.written("radius"));
            }
        }
        return new Light.Point(position, color, intensity, radius);
    }

    private static LightType.Compiled compile(Light.Point light) {
        Vector3d p = light.position();
        Vector3d power = light.color().scale(light.intensity());
        double radius = light.radius();
        if (radius == 0) {
            return new LightType.Compiled(new Lights.Light(new PointLightSampler(),
                    PointLightSampler.data(p.x(), p.y(), p.z(), power.x(), power.y(), power.z()), p));
        }
        Vector3d radiance = power.scale(1 / (Math.PI * radius * radius));
        return new LightType.Compiled(new Lights.Light(new SphereLightSampler(),
                SphereLightSampler.data(p.x(), p.y(), p.z(), radius, radiance.x(), radiance.y(), radiance.z()), null),
                new Sphere(p, radius), radiance);
    }
}
