package glint.recipe;

import glint.scene.Light;
import glint.registry.LightType;
import glint.math.Vector3d;
import glint.shading.LightSample;
import glint.shading.LightSampler;
import java.util.List;

/**
 * A light type added by the recipe of docs/architecture.md, in test sources only: a lamp at a point
 * whose irradiance does not fall off with distance, written {@code {type: lamp, position: [x, y, z]}}.
 */
record Lamp(Vector3d position, Vector3d color, double intensity) implements Light {

    static final LightType<Lamp> TYPE = new LightType<>("lamp", Lamp.class, List.of("position"),
            (fields, color, intensity) -> new Lamp(fields.vector("position"), color, intensity), Lamp::position,
            new Sampler(), true);

    /** The direction towards the position, and the power as irradiance at any distance. */
    static final class Sampler implements LightSampler {

        @Override
        public boolean sample(double[] vector, double[] power, int at, double px, double py, double pz,
                              LightSample out) {
            double lx = vector[at] - px, ly = vector[at + 1] - py, lz = vector[at + 2] - pz;
            double distance = Math.sqrt(lx * lx + ly * ly + lz * lz);
            if (distance == 0) {
                return false;
            }
            out.distance = distance;
            out.dirX = lx / distance;
            out.dirY = ly / distance;
            out.dirZ = lz / distance;
            out.irradianceR = power[at];
            out.irradianceG = power[at + 1];
            out.irradianceB = power[at + 2];
            return true;
        }
    }
}
