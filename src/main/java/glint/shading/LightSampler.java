package glint.shading;

/**
 * How one kind of light is seen from a surface point (pbrt-v4's Light, Mitsuba 3's Emitter): given
 * the point and two uniform numbers, the direction towards a point of the light, its distance, what
 * it brings and the density with which that direction was chosen ({@link #sample}); the density of
 * any direction ({@link #pdf}); its power ({@link #power}). It reads what the compiled scene keeps of
 * each light, a run of numbers in one flat array ({@link Lights}), so one sampler serves every light
 * of its kind. A light type ({@code glint.registry.LightType}) compiles its lights into these runs.
 */
public interface LightSampler {

    /**
     * The light whose numbers start at {@code data[at]}, seen from p, sampled by the uniform numbers u1
     * and u2 (which a delta light ignores), into {@code out}: the unit direction towards it, the
     * distance to the point sampled, the irradiance the sample stands for on a surface facing it
     * (a delta light's irradiance; otherwise the radiance arriving over the density) and the density
     * per solid angle (0 for a delta light). False (leaving {@code out} alone) where it has no
     * direction from p.
     */
    boolean sample(double[] data, int at, double px, double py, double pz, double u1, double u2, LightSample out);

    /**
     * The density per solid angle with which {@link #sample} chooses unit direction w from p: 0 for a
     * delta light and for a direction that misses the light.
     */
    double pdf(double[] data, int at, double px, double py, double pz, double wx, double wy, double wz);

    /** Whether all the light arriving from it at a point comes from one direction (a point, a sun of size 0). */
    boolean isDelta();

    /**
     * The light's power, the mean of its channels, in watts for a light at a point or with a body; a
     * light at infinity counts what falls on a disc of radius {@code sceneRadius} facing it.
     */
    double power(double[] data, int at, double sceneRadius);

    /**
     * Light leaving the light, sampled by the uniform numbers u1 to u4, into {@code out}: its origin,
     * direction, flux and densities ({@link LightRay}). A light at infinity sends its rays across a
     * disc of radius {@code sceneRadius} around the scene's centre c, facing them, from outside it,
     * from a point uniform over the disc. The densities are in proportion to the light sent, so the flux
     * is the same for every ray the light may leave by (what lets {@link LightTargets} aim rays
     * elsewhere). Over many samples the flux's mean channel is {@link #power}.
     */
    void leaving(double[] data, int at, double cx, double cy, double cz, double sceneRadius, double u1, double u2,
                 double u3, double u4, LightRay out);

    /**
     * The densities with which {@link #leaving} chooses the ray leaving point o of the light along unit
     * direction w, into {@code out.pdfOrigin} (per unit area; 1 for a point light) and {@code
     * out.pdfDirection} (per solid angle; 0 for a directional light's one direction), and the light's
     * normal at o into {@code out.normal}. For a light at infinity o is any point of its disc's
     * cylinder (the caller checks that it is one). What a bidirectional integrator weighs a path by.
     */
    void leavingPdf(double[] data, int at, double ox, double oy, double oz, double wx, double wy, double wz,
                    double sceneRadius, LightRay out);

    /**
     * Whether its light arrives along parallel rays from infinitely far (a directional light, a sun, the
     * sky): its rays leave a disc across the scene ({@link #leaving}).
     */
    default boolean infinitelyFar() {
        return atInfinity();
    }

    /**
     * The radiance arriving along unit direction d from a light at infinity, for a ray that escapes
     * the scene, into {@code out}; 0 for a light that is not seen that way.
     */
    default void arriving(double[] data, int at, double dx, double dy, double dz, Rgb out) {
        out.set(0, 0, 0);
    }

    /** Whether rays that escape the scene may see this light ({@link #arriving}): a sun with a size. */
    default boolean atInfinity() {
        return false;
    }
}
