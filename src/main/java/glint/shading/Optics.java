package glint.shading;

/** Fresnel factors and the microfacet terms of the cook-torrance model. Angles are given by cosines. */
public final class Optics {

    private Optics() {
    }

    /** The ratio of indices a ray meets at a dielectric of index ior: n_incident / n_transmitted. */
    public static double eta(double ior, boolean entering) {
        return entering ? 1 / ior : ior;
    }

    /**
     * Exact unpolarised Fresnel reflectance of a smooth dielectric boundary. {@code cosIncident}
     * is the cosine between the incident direction and the normal (>= 0), {@code eta} = n_incident /
     * n_transmitted. Returns 1 past the critical angle (total internal reflection).
     */
    public static double fresnelDielectric(double cosIncident, double eta) {
        double sin2Transmitted = eta * eta * Math.max(0, 1 - cosIncident * cosIncident);
        if (sin2Transmitted >= 1) {
            return 1;
        }
        double cosTransmitted = Math.sqrt(1 - sin2Transmitted);
        double rs = (eta * cosIncident - cosTransmitted) / (eta * cosIncident + cosTransmitted);
        double rp = (cosIncident - eta * cosTransmitted) / (cosIncident + eta * cosTransmitted);
        return 0.5 * (rs * rs + rp * rp);
    }

    /**
     * The refracted direction of unit direction d at a boundary with unit normal n facing the
     * incident side ({@code cosIncident} = -d.n >= 0, eta = n_incident / n_transmitted), written to
     * {@code out} as a unit vector. Returns false, leaving {@code out} alone, past the critical angle.
     */
    public static boolean refract(double dx, double dy, double dz, double nx, double ny, double nz,
                                  double cosIncident, double eta, double[] out) {
        double bend = refractionBend(cosIncident, eta);
        if (Double.isNaN(bend)) {
            return false;
        }
        refractWithBend(dx, dy, dz, nx, ny, nz, eta, bend, out);
        return true;
    }

    /**
     * The refracted direction's share of the normal, which depends on the angle alone: the
     * refracted direction is eta d + bend n, normalised. NaN past the critical angle.
     */
    public static double refractionBend(double cosIncident, double eta) {
        double sin2Transmitted = eta * eta * Math.max(0, 1 - cosIncident * cosIncident);
        if (sin2Transmitted >= 1) {
            return Double.NaN;
        }
        return eta * cosIncident - Math.sqrt(1 - sin2Transmitted);
    }

    /** {@link #refract} with its {@link #refractionBend} worked out already (not NaN). */
    public static void refractWithBend(double dx, double dy, double dz, double nx, double ny, double nz, double eta,
                                       double bend, double[] out) {
        double tx = eta * dx + bend * nx, ty = eta * dy + bend * ny, tz = eta * dz + bend * nz;
        double inv = 1 / Math.sqrt(tx * tx + ty * ty + tz * tz);
        out[0] = tx * inv;
        out[1] = ty * inv;
        out[2] = tz * inv;
    }

    /**
     * Schlick's approximation for a dielectric boundary, used correctly: F0 from the two indices and
     * the cosine on the less dense side (the transmitted one when leaving the denser medium), 1 past
     * the critical angle. Same arguments as {@link #fresnelDielectric}.
     */
    public static double schlickDielectric(double cosIncident, double eta) {
        double f0 = (eta - 1) / (eta + 1);
        f0 *= f0;
        if (eta <= 1) {
            return schlick(f0, cosIncident);
        }
        double sin2Transmitted = eta * eta * Math.max(0, 1 - cosIncident * cosIncident);
        if (sin2Transmitted >= 1) {
            return 1;
        }
        return schlick(f0, Math.sqrt(1 - sin2Transmitted));
    }

    /** Schlick's approximation F0 + (1 - F0)(1 - cos)^5, for one channel. */
    public static double schlick(double f0, double cosTheta) {
        double m = Math.min(1, Math.max(0, 1 - cosTheta));
        double m2 = m * m;
        return f0 + (1 - f0) * m2 * m2 * m;
    }

    /** The GGX (Trowbridge-Reitz) normal distribution D(h) with alpha = roughness^2. */
    public static double ggx(double cosHalf, double alpha) {
        double a2 = alpha * alpha;
        double k = cosHalf * cosHalf * (a2 - 1) + 1;
        return a2 / (Math.PI * k * k);
    }

    /**
     * Height-correlated Smith visibility V = G2 / (4 n.l n.v) for GGX (Heitz 2014, eq. 99), finite
     * for n.l, n.v > 0 and any alpha > 0.
     */
    public static double smithVisibility(double cosLight, double cosView, double alpha) {
        double a2 = alpha * alpha;
        double lambdaView = cosLight * Math.sqrt(cosView * cosView * (1 - a2) + a2);
        double lambdaLight = cosView * Math.sqrt(cosLight * cosLight * (1 - a2) + a2);
        return 0.5 / (lambdaView + lambdaLight);
    }
}
