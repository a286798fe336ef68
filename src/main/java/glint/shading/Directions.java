package glint.shading;

/**
 * Uniform directions over the sphere and over a disc, and cosine-weighted ones about an axis: how
 * light leaving a light is sampled. Each writes into a scratch array of three.
 */
final class Directions {

    private Directions() {
    }

    /** A unit direction uniform over the sphere (density 1 / (4 pi)) from u1 and u2, into {@code out}. */
    static void uniform(double u1, double u2, double[] out) {
        double z = 1 - 2 * u1;
        double r = Math.sqrt(Math.max(0, 1 - z * z));
        double phi = 2 * Math.PI * u2;
        out[0] = r * Math.cos(phi);
        out[1] = r * Math.sin(phi);
        out[2] = z;
    }

    /**
     * A unit direction about unit axis a with density cos / pi (Malley's method) from u1 and u2, into
     * {@code out}; returns its cosine to the axis.
     */
    static double cosineAbout(double ax, double ay, double az, double u1, double u2, double[] out) {
        double r = Math.sqrt(u1), phi = 2 * Math.PI * u2;
        double x = r * Math.cos(phi), y = r * Math.sin(phi), z = Math.sqrt(Math.max(0, 1 - u1));
        toWorld(ax, ay, az, x, y, z, out);
        return z;
    }

    /**
     * A point of the disc of radius {@code radius} centred at c and facing unit axis a, uniform over
     * its area (density 1 / (pi radius^2)) from u1 and u2, into {@code out}.
     */
    static void onDisc(double cx, double cy, double cz, double ax, double ay, double az, double radius, double u1,
                       double u2, double[] out) {
        double r = radius * Math.sqrt(u1), phi = 2 * Math.PI * u2;
        toWorld(ax, ay, az, r * Math.cos(phi), r * Math.sin(phi), 0, out);
        out[0] += cx;
        out[1] += cy;
        out[2] += cz;
    }

    /** (x, y, z) in a basis (t, b, a) around unit axis a, built without a branch (Duff et al. 2017), into out. */
    private static void toWorld(double ax, double ay, double az, double x, double y, double z, double[] out) {
        double sign = Math.copySign(1.0, az);
        double k = -1 / (sign + az);
        double m = ax * ay * k;
        double tx = 1 + sign * ax * ax * k, ty = sign * m, tz = -sign * ax;
        double bx = m, by = sign + ay * ay * k, bz = -ay;
        out[0] = x * tx + y * bx + z * ax;
        out[1] = x * ty + y * by + z * ay;
        out[2] = x * tz + y * bz + z * az;
    }
}
