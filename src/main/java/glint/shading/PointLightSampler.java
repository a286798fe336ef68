package glint.shading;

/**
 * A point light, its numbers [x, y, z, R, G, B]: the position and the radiant intensity (colour x
 * intensity); inverse-square irradiance along the direction to it. A delta light.
 */
public final class PointLightSampler implements DeltaLightSampler {

    /** How many numbers a point light keeps. */
    public static final int SIZE = 6;

    /**
     * The largest 1/d^2 taken: a light nearer than 1e-125 lights as one 1e-125 away, so that 100,000
     * lights of 1e30, the brightest, still sum to a finite double (1e285), which no factor of 0 makes NaN.
     */
    static final double LARGEST_SCALE = 1e250;

    /** The numbers of a point light at p of radiant intensity i per channel. */
    public static double[] data(double px, double py, double pz, double r, double g, double b) {
        return new double[] {px, py, pz, r, g, b};
    }

    @Override
    public boolean sample(double[] data, int at, double px, double py, double pz, double u1, double u2,
                          LightSample out) {
        double lx = data[at] - px, ly = data[at + 1] - py, lz = data[at + 2] - pz;
        double distance2 = lx * lx + ly * ly + lz * lz;
        if (distance2 == 0) {
            return false;
        }
        double inv = 1 / Math.sqrt(distance2);
        out.setDirection(lx * inv, ly * inv, lz * inv, distance2 * inv);
        double scale = Math.min(inv * inv, LARGEST_SCALE);
        out.setIrradiance(data[at + 3] * scale, data[at + 4] * scale, data[at + 5] * scale);
        out.pdf = 0;
        return true;
    }

    /** From the position, a direction uniform over the sphere: the flux 4 pi I. */
    @Override
    public void leaving(double[] data, int at, double cx, double cy, double cz, double sceneRadius, double u1,
                        double u2, double u3, double u4, LightRay out) {
        double[] w = out.scratch;
        Directions.uniform(u1, u2, w);
        out.setOrigin(data[at], data[at + 1], data[at + 2]);
        out.setNormal(0, 0, 0);
        out.setDirection(w[0], w[1], w[2]);
        double k = 4 * Math.PI;
        out.setFlux(data[at + 3] * k, data[at + 4] * k, data[at + 5] * k);
        out.pdfOrigin = 1;
        out.pdfDirection = 1 / k;
    }

    /** Its one point, a direction uniform over the sphere. */
    @Override
    public void leavingPdf(double[] data, int at, double ox, double oy, double oz, double wx, double wy, double wz,
                           double sceneRadius, LightRay out) {
        out.setNormal(0, 0, 0);
        out.pdfOrigin = 1;
        out.pdfDirection = 1 / (4 * Math.PI);
    }

    /** 4 pi times the radiant intensity. */
    @Override
    public double power(double[] data, int at, double sceneRadius) {
        return 4 * Math.PI * (data[at + 3] + data[at + 4] + data[at + 5]) / 3;
    }
}
