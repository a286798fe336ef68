package glint.shading;

/**
 * The background as a light (a sky): radiance [R, G, B] arriving along every direction of a ray that
 * escapes the scene. Sampled uniformly over the sphere (density 1 / (4 pi)); its light leaves a disc
 * across the scene, of the scene's radius, facing a direction uniform over the sphere. Not a light of
 * the scene file: what a bidirectional integrator starts the sky's light paths from, and samples it by.
 */
public final class SkySampler implements LightSampler {

    /** The numbers of a sky of radiance c per channel. */
    public static double[] data(double r, double g, double b) {
        return new double[] {r, g, b};
    }

    @Override
    public boolean sample(double[] data, int at, double px, double py, double pz, double u1, double u2,
                          LightSample out) {
        double[] w = out.scratch;
        Directions.uniform(u1, u2, w);
        out.setDirection(w[0], w[1], w[2], Double.POSITIVE_INFINITY);
        double k = 4 * Math.PI; // radiance over the density
        out.setIrradiance(data[at] * k, data[at + 1] * k, data[at + 2] * k);
        out.pdf = 1 / k;
        return true;
    }

    @Override
    public double pdf(double[] data, int at, double px, double py, double pz, double wx, double wy, double wz) {
        return 1 / (4 * Math.PI);
    }

    /** A direction uniform over the sphere, then a point of the disc facing it: the flux L 4 pi pi R^2. */
    @Override
    public void leaving(double[] data, int at, double cx, double cy, double cz, double sceneRadius, double u1,
                        double u2, double u3, double u4, LightRay out) {
        double[] w = out.scratch;
        Directions.uniform(u1, u2, w);
        double tx = w[0], ty = w[1], tz = w[2]; // towards the sky
        Directions.onDisc(cx + tx * sceneRadius, cy + ty * sceneRadius, cz + tz * sceneRadius, tx, ty, tz,
                sceneRadius, u3, u4, out.frame, w);
        out.setOrigin(w[0], w[1], w[2]);
        out.setDirection(-tx, -ty, -tz);
        out.setNormal(0, 0, 0);
        double area = Math.PI * sceneRadius * sceneRadius;
        double k = 4 * Math.PI * area;
        out.setFlux(data[at] * k, data[at + 1] * k, data[at + 2] * k);
        out.pdfOrigin = 1 / area;
        out.pdfDirection = 1 / (4 * Math.PI);
    }

    @Override
    public void leavingPdf(double[] data, int at, double ox, double oy, double oz, double wx, double wy, double wz,
                           double sceneRadius, LightRay out) {
        out.setNormal(0, 0, 0);
        out.pdfOrigin = 1 / (Math.PI * sceneRadius * sceneRadius);
        out.pdfDirection = 1 / (4 * Math.PI);
    }

    @Override
    public boolean isDelta() {
        return false;
    }

    /** The light crossing a disc of the scene's radius from every direction: L 4 pi pi R^2. */
    @Override
    public double power(double[] data, int at, double sceneRadius) {
        return 4 * Math.PI * Math.PI * sceneRadius * sceneRadius * (data[at] + data[at + 1] + data[at + 2]) / 3;
    }

    @Override
    public void arriving(double[] data, int at, double dx, double dy, double dz, Rgb out) {
        out.set(data[at], data[at + 1], data[at + 2]);
    }

    @Override
    public boolean atInfinity() {
        return true;
    }
}
