package glint.recipe;

import glint.shading.LightSample;
import glint.shading.LightSampler;

/** How shading samples a {@link Lamp}: the direction towards its position, and its power as irradiance at any distance. */
final class LampSampler implements LightSampler {

    @Override
    public boolean sample(double[] vector, double[] power, int at, double px, double py, double pz, LightSample out) {
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
