package glint.shading;

/**
 * How one light type is seen from a surface point: the direction towards it, its distance and the
 * irradiance it brings, from what the compiled scene keeps of each light (a vector and the power).
 */
public interface LightSampler {

    /**
     * The light whose vector is {@code vector[at..at+2]} and power (colour x intensity)
     * {@code power[at..at+2]}, seen from p, into {@code out}; false (leaving {@code out} alone)
     * where it has no direction from p.
     */
    boolean sample(double[] vector, double[] power, int at, double px, double py, double pz, LightSample out);
}
