package glint.recipe;

import glint.shading.LightSample;
import glint.shading.LightSampler;

/**
 * How shading samples a {@link Lamp}, its numbers [x, y, z, R, G, B]: the direction towards its
 * position, and its power as irradiance at any distance. A delta light.
 */
final class LampSampler implements LightSampler {

    @Override
    public boolean sample(double[] data, int at, double px, double py, double pz, double u1, double u2,
                          LightSample out) {
        double lx = data[at] - px, ly = data[at + 1] - py, lz = data[at + 2] - pz;
        double distance = Math.sqrt(lx * lx + ly * ly + lz * lz);
        if (distance == 0) {
            return false;
        }
        out.distance = distance;
        out.dirX = lx / distance;
        out.dirY = ly / distance;
        out.dirZ = lz / distance;
        out.irradianceR = data[at + 3];
        out.irradianceG = data[at + 4];
        out.irradianceB = data[at + 5];
        out.pdf = 0;
        return true;
    }

    @Override
    public double pdf(double[] data, int at, double px, double py, double pz, double wx, double wy, double wz) {
        return 0;
    }

    @Override
    public boolean isDelta() {
        return true;
    }

    /** The irradiance over a disc of the scene's radius, as a directional light's. */
    @Override
    public double power(double[] data, int at, double sceneRadius) {
        return Math.PI * sceneRadius * sceneRadius * (data[at + 3] + data[at + 4] + data[at + 5]) / 3;
    }
}
