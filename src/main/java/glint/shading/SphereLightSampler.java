package glint.shading;

/**
 * A sphere light (a point light with a radius), its numbers [x, y, z, r, R, G, B]: the centre, the
 * radius and the radiance its surface sends uniformly, colour x intensity / (pi r^2), so that it has
 * the power and, from afar, the radiant intensity of the point light it becomes as r shrinks. Seen
 * from a point outside it, it is sampled uniformly over the cone it subtends; from inside it has no
 * direction. Its body, a black sphere, is a primitive of the scene that rays meet.
 */
public final class SphereLightSampler implements LightSampler {

    /** How many numbers a sphere light keeps. */
    public static final int SIZE = 7;

    /** The numbers of a sphere light at c of radius r whose surface sends radiance l per channel. */
    public static double[] data(double cx, double cy, double cz, double radius, double r, double g, double b) {
        return new double[] {cx, cy, cz, radius, r, g, b};
    }

    @Override
    public boolean sample(double[] data, int at, double px, double py, double pz, double u1, double u2,
                          LightSample out) {
        double lx = data[at] - px, ly = data[at + 1] - py, lz = data[at + 2] - pz;
        double radius = data[at + 3];
        double distance2 = lx * lx + ly * ly + lz * lz;
        double sin2Max = radius * radius / distance2;
        if (!(sin2Max < 1)) { // on or inside the light, or NaN
            return false;
        }
        double oneMinusCos = Cone.oneMinusCos(sin2Max);
        if (!(oneMinusCos > 0)) { // so far off that its cone is no width a double holds
            return false;
        }
        double distance = Math.sqrt(distance2);
        double inv = 1 / distance;
        double sin2 = Cone.sample(lx * inv, ly * inv, lz * inv, oneMinusCos, u1, u2, out);
        double cos = Math.sqrt(Math.max(0, 1 - sin2));
        // the nearer of the two points where the direction meets the sphere
        out.distance = distance * cos - Math.sqrt(Math.max(0, radius * radius - distance2 * sin2));
        Cone.setLight(oneMinusCos, data[at + 4], data[at + 5], data[at + 6], out);
        return true;
    }

    @Override
    public double pdf(double[] data, int at, double px, double py, double pz, double wx, double wy, double wz) {
        double lx = data[at] - px, ly = data[at + 1] - py, lz = data[at + 2] - pz;
        double radius = data[at + 3];
        double distance2 = lx * lx + ly * ly + lz * lz;
        double sin2Max = radius * radius / distance2;
        if (!(sin2Max < 1)) {
            return 0;
        }
        double oneMinusCos = Cone.oneMinusCos(sin2Max);
        double inv = 1 / Math.sqrt(distance2);
        boolean within = oneMinusCos > 0 && Cone.contains(lx * inv, ly * inv, lz * inv, sin2Max, wx, wy, wz);
        return within ? Cone.pdf(oneMinusCos) : 0;
    }

    /**
     * From a point uniform over the sphere (density 1 / (4 pi r^2)), a direction about its outward
     * normal with density cos / pi: the flux L pi 4 pi r^2, the power.
     */
    @Override
    public void leaving(double[] data, int at, double cx, double cy, double cz, double sceneRadius, double u1,
                        double u2, double u3, double u4, LightRay out) {
        double radius = data[at + 3];
        double[] v = out.scratch;
        Directions.uniform(u1, u2, v);
        double nx = v[0], ny = v[1], nz = v[2];
        out.setOrigin(data[at] + radius * nx, data[at + 1] + radius * ny, data[at + 2] + radius * nz);
        out.setNormal(nx, ny, nz);
        double cos = Directions.cosineAbout(nx, ny, nz, u3, u4, out.frame, v);
        out.setDirection(v[0], v[1], v[2]);
        double area = 4 * Math.PI * radius * radius;
        double k = Math.PI * area; // L cos / ((1 / area) (cos / pi))
        out.setFlux(data[at + 4] * k, data[at + 5] * k, data[at + 6] * k);
        out.pdfOrigin = 1 / area;
        out.pdfDirection = cos / Math.PI;
    }

    /** Origin uniform over the sphere, direction cos / pi about the outward normal at o. */
    @Override
    public void leavingPdf(double[] data, int at, double ox, double oy, double oz, double wx, double wy, double wz,
                           double sceneRadius, LightRay out) {
        double radius = data[at + 3];
        double inv = 1 / radius;
        double nx = (ox - data[at]) * inv, ny = (oy - data[at + 1]) * inv, nz = (oz - data[at + 2]) * inv;
        out.setNormal(nx, ny, nz);
        out.pdfOrigin = 1 / (4 * Math.PI * radius * radius);
        out.pdfDirection = Math.max(0, nx * wx + ny * wy + nz * wz) / Math.PI;
    }

    @Override
    public boolean isDelta() {
        return false;
    }

    /** The radiance times pi (a Lambertian emitter's exitance) times the surface's area, 4 pi r^2. */
    @Override
    public double power(double[] data, int at, double sceneRadius) {
        double radius = data[at + 3];
        return Math.PI * 4 * Math.PI * radius * radius * (data[at + 4] + data[at + 5] + data[at + 6]) / 3;
    }
}
