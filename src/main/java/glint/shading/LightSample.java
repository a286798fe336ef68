package glint.shading;

/** Scratch value: one light seen from a surface point (world space), as its sampler chose it. */
public final class LightSample {

    /** Unit direction towards the point of the light sampled. */
    public double dirX, dirY, dirZ;
    /** |n.l|: the cosine between the surface's normal and the direction towards the light. */
    public double cosine;
    /** Distance to the point of the light sampled; infinite for a light at infinity. */
    public double distance;
    /**
     * The irradiance the sample stands for on a surface facing the light: a delta light's irradiance,
     * otherwise the radiance arriving along the direction over {@link #pdf}.
     */
    public double irradianceR, irradianceG, irradianceB;
    /** The density per solid angle with which the direction was chosen; 0 for a delta light. */
    public double pdf;

    /** Scratch of the samplers: a basis around the axis of the cone a light covers. */
    final ShadingFrame frame = new ShadingFrame();
    /** Scratch of the samplers: a direction. */
    final double[] scratch = new double[3];

    /** Sets the irradiance the sample stands for, per channel. */
    void setIrradiance(double r, double g, double b) {
        irradianceR = r;
        irradianceG = g;
        irradianceB = b;
    }

    /** Sets the unit direction and the distance. */
    void setDirection(double x, double y, double z, double distanceToLight) {
        dirX = x;
        dirY = y;
        dirZ = z;
        distance = distanceToLight;
    }
}
