package glint.scene;

import glint.math.Vector3d;
import glint.shading.DirectionalLightSampler;
import glint.shading.PointLightSampler;
import java.util.List;

/** A light of the scene model; its {@link LightType} says how it is read, compiled and sampled. */
public interface Light {

    /** The colour; {@code color} times {@code intensity} is the light's power. */
    Vector3d color();

    double intensity();

    /** A point light of radiant intensity color x intensity, falling off as 1/d^2. */
    record Point(Vector3d position, Vector3d color, double intensity) implements Light {

        /** {@code {type: point, position: [x, y, z]}}: its position kept, sampled by {@link PointLightSampler}. */
        public static final LightType<Point> TYPE = new LightType<>("point", Point.class, List.of("position"),
                (fields, color, intensity) -> new Point(fields.vector("position"), color, intensity),
                Point::position, new PointLightSampler(), true);
    }

    /** A directional light; {@code direction} (unit) is the way its light travels. */
    record Directional(Vector3d direction, Vector3d color, double intensity) implements Light {

        /**
         * {@code {type: directional, direction: [x, y, z]}}: the direction towards it kept, sampled by
         * {@link DirectionalLightSampler}.
         */
        public static final LightType<Directional> TYPE = new LightType<>("directional", Directional.class,
                List.of("direction"),
                (fields, color, intensity) -> new Directional(fields.direction("direction"), color, intensity),
                light -> light.direction().scale(-1), new DirectionalLightSampler(), false);
    }
}
