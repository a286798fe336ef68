package glint.shading;

/**
 * Directions spread uniformly over a cone of solid angle 2 pi (1 - cos theta_max) around a unit
 * axis: how a light with a size seen from a point (a sphere, a sun's disc) is sampled. The cone is
 * given by 1 - cos theta_max, which stays exact for cones far narrower than a rounding step of the
 * cosine (a sphere of radius 1e-4 ten units away: 5e-11).
 */
final class Cone {

    private Cone() {
    }

    /** 1 - cos theta_max of a cone whose sin^2 theta_max is {@code sin2}, without cancellation. */
    static double oneMinusCos(double sin2) {
        return sin2 / (1 + Math.sqrt(Math.max(0, 1 - sin2)));
    }

    /** The density per solid angle of a direction chosen uniformly in the cone. */
    static double pdf(double oneMinusCos) {
        return 1 / (2 * Math.PI * oneMinusCos);
    }

    /**
     * Sets what a direction sampled uniformly in the cone stands for when the light covering it sends
     * radiance l per channel: irradiance l x the cone's solid angle (radiance over the density), and the
     * density.
     */
    static void setLight(double oneMinusCos, double r, double g, double b, LightSample out) {
        double solidAngle = solidAngle(oneMinusCos);
        out.setIrradiance(r * solidAngle, g * solidAngle, b * solidAngle);
        out.pdf = 1 / solidAngle;
    }

    /** The cone's solid angle, 2 pi (1 - cos theta_max). */
    static double solidAngle(double oneMinusCos) {
        return 2 * Math.PI * oneMinusCos;
    }

    /**
     * Whether unit direction w lies within the cone around unit axis a of {@code sin2} = sin^2
     * theta_max (a cone narrower than a hemisphere): in front of it, at most theta_max off, compared
     * through |w x a|^2 so that a narrow cone's edge is not lost to the cosine's rounding.
     */
    static boolean contains(double ax, double ay, double az, double sin2, double wx, double wy, double wz) {
        double cos = ax * wx + ay * wy + az * wz;
        double cx = ay * wz - az * wy, cy = az * wx - ax * wz, cz = ax * wy - ay * wx;
        return cos > 0 && cx * cx + cy * cy + cz * cz <= sin2;
    }

    /**
     * A direction within the cone around unit axis a of {@code oneMinusCos} = 1 - cos theta_max from
     * the uniform numbers u1 (the angle off the axis) and u2 (around it), into {@code out}'s direction
     * (its distance left alone); returns sin^2 of its angle off the axis.
     */
    static double sample(double ax, double ay, double az, double oneMinusCos, double u1, double u2,
                         LightSample out) {
        double[] w = out.scratch;
        double sin2 = sample(ax, ay, az, oneMinusCos, u1, u2, out.frame, w);
        out.dirX = w[0];
        out.dirY = w[1];
        out.dirZ = w[2];
        return sin2;
    }

    /**
     * As {@link #sample(double, double, double, double, double, double, LightSample)}, the direction into
     * {@code out}[0..2], with {@code frame} as scratch.
     */
    static double sample(double ax, double ay, double az, double oneMinusCos, double u1, double u2,
                         ShadingFrame frame, double[] out) {
        double down = u1 * oneMinusCos; // 1 - cos theta
        double cos = 1 - down;
        double sin2 = down * (2 - down);
        double sin = Math.sqrt(sin2);
        double phi = 2 * Math.PI * u2;
        double x = sin * Math.cos(phi), y = sin * Math.sin(phi);
        frame.set(ax, ay, az);
        out[0] = frame.worldX(x, y, cos);
        out[1] = frame.worldY(x, y, cos);
        out[2] = frame.worldZ(x, y, cos);
        return sin2;
    }
}
