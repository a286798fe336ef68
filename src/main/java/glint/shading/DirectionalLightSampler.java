package glint.shading;

/**
 * A directional light (its vector the unit direction towards it): the same irradiance from the
 * same direction everywhere.
 */
public final class DirectionalLightSampler implements LightSampler {

    @Override
    public boolean sample(double[] vector, double[] power, int at, double px, double py, double pz,
                          LightSample out) {
        out.dirX = vector[at];
        out.dirY = vector[at + 1];
        out.dirZ = vector[at + 2];
        out.distance = Double.POSITIVE_INFINITY;
        out.irradianceR = power[at];
        out.irradianceG = power[at + 1];
        out.irradianceB = power[at + 2];
        return true;
    }
}
