package glint.shading;

/**
 * A directional light of size 0, its numbers [x, y, z, R, G, B]: the unit direction towards it and
 * the irradiance on a surface facing it; the same from everywhere. A delta light.
 */
public final class DirectionalLightSampler implements DeltaLightSampler {

    /** How many numbers a directional light keeps. */
    public static final int SIZE = 6;

    /** The numbers of a directional light towards unit direction w of irradiance e per channel. */
    public static double[] data(double wx, double wy, double wz, double r, double g, double b) {
        return new double[] {wx, wy, wz, r, g, b};
    }

    @Override
    public boolean sample(double[] data, int at, double px, double py, double pz, double u1, double u2,
                          LightSample out) {
        out.setDirection(data[at], data[at + 1], data[at + 2], Double.POSITIVE_INFINITY);
        out.setIrradiance(data[at + 3], data[at + 4], data[at + 5]);
        out.pdf = 0;
        return true;
    }

    /**
     * Along the light's direction, from a point of the disc of the scene's radius facing it, outside the
     * scene: the flux E pi R^2.
     */
    @Override
    public void leaving(double[] data, int at, double cx, double cy, double cz, double sceneRadius, double u1,
                        double u2, double u3, double u4, LightRay out) {
        double tx = data[at], ty = data[at + 1], tz = data[at + 2]; // towards the light
        double[] p = out.scratch;
        Directions.onDisc(cx + tx * sceneRadius, cy + ty * sceneRadius, cz + tz * sceneRadius, tx, ty, tz,
                sceneRadius, u1, u2, out.frame, p);
        out.setOrigin(p[0], p[1], p[2]);
        out.setNormal(0, 0, 0);
        out.setDirection(-tx, -ty, -tz);
        double area = Math.PI * sceneRadius * sceneRadius;
        out.setFlux(data[at + 3] * area, data[at + 4] * area, data[at + 5] * area);
        out.pdfOrigin = 1 / area;
        out.pdfDirection = 1;
    }

    /** A point uniform over the disc; its one direction, which has no density. */
    @Override
    public void leavingPdf(double[] data, int at, double ox, double oy, double oz, double wx, double wy, double wz,
                           double sceneRadius, LightRay out) {
        out.setNormal(0, 0, 0);
        out.pdfOrigin = 1 / (Math.PI * sceneRadius * sceneRadius);
        out.pdfDirection = 0;
    }

    @Override
    public boolean infinitelyFar() {
        return true;
    }

    /** The irradiance over a disc of the scene's radius. */
    @Override
    public double power(double[] data, int at, double sceneRadius) {
        return Math.PI * sceneRadius * sceneRadius * (data[at + 3] + data[at + 4] + data[at + 5]) / 3;
    }
}
