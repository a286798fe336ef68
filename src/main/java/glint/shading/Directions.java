package glint.shading;

/**
 * Uniform directions over the sphere, cosine-weighted ones about an axis and points of a disc: how
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
     * {@code out}, with {@code frame} as scratch; returns its cosine to the axis.
     */
    static double cosineAbout(double ax, double ay, double az, double u1, double u2, ShadingFrame frame,
                              double[] out) {
        double r = Math.sqrt(u1), phi = 2 * Math.PI * u2;
        double x = r * Math.cos(phi), y = r * Math.sin(phi), z = Math.sqrt(Math.max(0, 1 - u1));
        frame.set(ax, ay, az);
        out[0] = frame.worldX(x, y, z);
        out[1] = frame.worldY(x, y, z);
        out[2] = frame.worldZ(x, y, z);
        return z;
    }

    /**
     * A point of the disc of radius {@code radius} centred at c and facing unit axis a, uniform over
     * its area (density 1 / (pi radius^2)) from u1 and u2, into {@code out}, with {@code frame} as scratch.
     */
    static void onDisc(double cx, double cy, double cz, double ax, double ay, double az, double radius, double u1,
                       double u2, ShadingFrame frame, double[] out) {
        double r = radius * Math.sqrt(u1), phi = 2 * Math.PI * u2;
        double x = r * Math.cos(phi), y = r * Math.sin(phi);
        frame.set(ax, ay, az);
        out[0] = cx + frame.worldX(x, y, 0);
        out[1] = cy + frame.worldY(x, y, 0);
        out[2] = cz + frame.worldZ(x, y, 0);
    }
}
