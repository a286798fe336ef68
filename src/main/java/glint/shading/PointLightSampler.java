package glint.shading;

/** A point light (its vector the position): inverse-square irradiance along the direction to it. */
public final class PointLightSampler implements LightSampler {

    /**
     * The largest 1/d^2 taken: a light nearer than 1e-125 lights as one 1e-125 away, so that 100,000
     * lights of 1e30, the brightest, still sum to a finite double (1e285), which no factor of 0 makes NaN.
     */
    static final double LARGEST_SCALE = 1e250;

    @Override
    public boolean sample(double[] vector, double[] power, int at, double px, double py, double pz,
                          LightSample out) {
        double lx = vector[at] - px, ly = vector[at + 1] - py, lz = vector[at + 2] - pz;
        double distance2 = lx * lx + ly * ly + lz * lz;
        if (distance2 == 0) {
            return false;
        }
        double inv = 1 / Math.sqrt(distance2);
        out.distance = distance2 * inv;
        out.dirX = lx * inv;
        out.dirY = ly * inv;
        out.dirZ = lz * inv;
        double scale = Math.min(inv * inv, LARGEST_SCALE);
        out.irradianceR = power[at] * scale;
        out.irradianceG = power[at + 1] * scale;
        out.irradianceB = power[at + 2] * scale;
        return true;
    }
}
