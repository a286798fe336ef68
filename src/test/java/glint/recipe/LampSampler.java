package glint.recipe;

import glint.shading.DeltaLightSampler;
import glint.shading.LightRay;
import glint.shading.LightSample;

/**
 * How shading samples a {@link Lamp}, its numbers [x, y, z, R, G, B]: the direction towards its
 * position, and its power as irradiance at any distance. A delta light.
 */
final class LampSampler implements DeltaLightSampler {

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

    /** From the position, a direction uniform over the sphere, carrying the power. */
    @Override
    public void leaving(double[] data, int at, double cx, double cy, double cz, double sceneRadius, double u1,
                        double u2, double u3, double u4, LightRay out) {
        double z = 1 - 2 * u1, r = Math.sqrt(Math.max(0, 1 - z * z)), phi = 2 * Math.PI * u2;
        out.originX = data[at];
        out.originY = data[at + 1];
        out.originZ = data[at + 2];
        out.dirX = r * Math.cos(phi);
        out.dirY = r * Math.sin(phi);
        out.dirZ = z;
        double area = Math.PI * sceneRadius * sceneRadius;
        out.fluxR = data[at + 3] * area;
        out.fluxG = data[at + 4] * area;
        out.fluxB = data[at + 5] * area;
        out.pdfOrigin = 1;
        out.pdfDirection = 1 / (4 * Math.PI);
    }

    /** Its one point, a direction uniform over the sphere. */
    @Override
    public void leavingPdf(double[] data, int at, double ox, double oy, double oz, double wx, double wy, double wz,
                           double sceneRadius, LightRay out) {
        out.normalX = 0;
        out.normalY = 0;
        out.normalZ = 0;
        out.pdfOrigin = 1;
        out.pdfDirection = 1 / (4 * Math.PI);
    }

    /** The irradiance over a disc of the scene's radius, as a directional light's. */
    @Override
    public double power(double[] data, int at, double sceneRadius) {
        return Math.PI * sceneRadius * sceneRadius * (data[at + 3] + data[at + 4] + data[at + 5]) / 3;
    }
}
