package glint.shading;

/**
 * A directional light with a size (a sun), its numbers [x, y, z, 1 - cos, sin^2, R, G, B]: the unit
 * direction towards its centre, the disc's angular radius theta (as 1 - cos theta and sin^2 theta)
 * and the disc's uniform radiance, colour x intensity / (pi sin^2 theta), which gives the irradiance
 * colour x intensity on a surface facing its centre. Sampled uniformly over its disc; a ray that
 * escapes the scene within the disc sees it.
 */
public final class SunSampler implements LightSampler {

    /** How many numbers a sun keeps. */
    public static final int SIZE = 8;

    /**
     * The numbers of a sun towards unit direction w of angular radius {@code radiusRadians} (in (0, pi/2))
     * giving irradiance e per channel on a surface facing it.
     */
    public static double[] data(double wx, double wy, double wz, double radiusRadians, double r, double g,
                                double b) {
        double sin = Math.sin(radiusRadians);
        double sin2 = sin * sin;
        double toRadiance = 1 / (Math.PI * sin2);
        return new double[] {wx, wy, wz, Cone.oneMinusCos(sin2), sin2, r * toRadiance, g * toRadiance,
                b * toRadiance};
    }

    @Override
    public boolean sample(double[] data, int at, double px, double py, double pz, double u1, double u2,
                          LightSample out) {
        double oneMinusCos = data[at + 3];
        Cone.sample(data[at], data[at + 1], data[at + 2], oneMinusCos, u1, u2, out);
        out.distance = Double.POSITIVE_INFINITY;
        Cone.setLight(oneMinusCos, data[at + 5], data[at + 6], data[at + 7], out);
        return true;
    }

    @Override
    public double pdf(double[] data, int at, double px, double py, double pz, double wx, double wy, double wz) {
        return within(data, at, wx, wy, wz) ? Cone.pdf(data[at + 3]) : 0;
    }

    /**
     * A direction uniform over the sun's cone, then a point of the disc of the scene's radius facing
     * it, outside the scene: the flux L x solid angle x pi R^2, the power.
     */
    @Override
    public void leaving(double[] data, int at, double cx, double cy, double cz, double sceneRadius, double u1,
                        double u2, double u3, double u4, LightRay out) {
        double oneMinusCos = data[at + 3];
        LightSample towards = out.towards;
        Cone.sample(data[at], data[at + 1], data[at + 2], oneMinusCos, u1, u2, towards);
        double tx = towards.dirX, ty = towards.dirY, tz = towards.dirZ;
        double[] p = out.scratch;
        Directions.onDisc(cx + tx * sceneRadius, cy + ty * sceneRadius, cz + tz * sceneRadius, tx, ty, tz,
                sceneRadius, u3, u4, out.frame, p);
        out.setOrigin(p[0], p[1], p[2]);
        out.setNormal(0, 0, 0);
        out.setDirection(-tx, -ty, -tz);
        double area = Math.PI * sceneRadius * sceneRadius;
        double k = Cone.solidAngle(oneMinusCos) * area;
        out.setFlux(data[at + 5] * k, data[at + 6] * k, data[at + 7] * k);
        out.pdfOrigin = 1 / area;
        out.pdfDirection = Cone.pdf(oneMinusCos);
    }

    /** A point uniform over the disc; the direction uniform over the sun's cone (towards the light: -w). */
    @Override
    public void leavingPdf(double[] data, int at, double ox, double oy, double oz, double wx, double wy, double wz,
                           double sceneRadius, LightRay out) {
        out.setNormal(0, 0, 0);
        out.pdfOrigin = 1 / (Math.PI * sceneRadius * sceneRadius);
        out.pdfDirection = pdf(data, at, ox, oy, oz, -wx, -wy, -wz);
    }

    @Override
    public boolean isDelta() {
        return false;
    }

    /**
     * The light crossing a disc of the scene's radius from every direction of the sun's: the radiance x
     * the disc's solid angle x pi radius^2 (the scene's cross-section, seen from any direction).
     */
    @Override
    public double power(double[] data, int at, double sceneRadius) {
        double radianceTimesSolidAngle = Cone.solidAngle(data[at + 3]) * (data[at + 5] + data[at + 6] + data[at + 7]) / 3;
        return Math.PI * sceneRadius * sceneRadius * radianceTimesSolidAngle;
    }

    @Override
    public void arriving(double[] data, int at, double dx, double dy, double dz, Rgb out) {
        if (within(data, at, dx, dy, dz)) {
            out.set(data[at + 5], data[at + 6], data[at + 7]);
        } else {
            out.set(0, 0, 0);
        }
    }

    @Override
    public boolean atInfinity() {
        return true;
    }

    private static boolean within(double[] data, int at, double wx, double wy, double wz) {
        return Cone.contains(data[at], data[at + 1], data[at + 2], data[at + 4], wx, wy, wz);
    }
}
