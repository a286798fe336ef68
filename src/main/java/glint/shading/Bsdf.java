package glint.shading;

/**
 * The materials' scattering, one function per material and term, shared by both shading models
 * and every ray. Cosines are of unit vectors; channels are linear RGB.
 */
public final class Bsdf {

    private static final double INV_PI = 1 / Math.PI;

    private Bsdf() {
    }

    /** Lambert, one channel: albedo / pi x the irradiance summed over the lights it sees (n.l applied), plus ambient x albedo. */
    public static double lambert(double albedo, double irradiance, double ambient) {
        return albedo * (irradiance * INV_PI + ambient);
    }

    /**
     * Adds a conductor's GGX highlight from one light to {@code sum}: D(h) V(l, v) n.l x F(v.h) x
     * the light's irradiance, F Schlick's with F0 = the material's colour. The view direction is
     * -d; the sample's direction is the unit direction to the light, {@code cosLight} = n.l > 0.
     */
    public static void addConductorHighlight(Materials materials, int m, Surface s, LightSample l, double cosLight,
                                             double dx, double dy, double dz, Rgb sum) {
        double alpha = materials.alpha(m);
        double hx = l.dirX - dx, hy = l.dirY - dy, hz = l.dirZ - dz;
        double inv = 1 / Math.sqrt(hx * hx + hy * hy + hz * hz);
        double cosHalf = (hx * s.nx + hy * s.ny + hz * s.nz) * inv;
        double cosViewHalf = Math.max(0, -(hx * dx + hy * dy + hz * dz) * inv);
        double specular = Optics.ggx(cosHalf, alpha) * Optics.smithVisibility(cosLight, s.cosIncident, alpha) * cosLight;
        sum.r += specular * Optics.schlick(materials.color(m, 0), cosViewHalf) * l.irradianceR;
        sum.g += specular * Optics.schlick(materials.color(m, 1), cosViewHalf) * l.irradianceG;
        sum.b += specular * Optics.schlick(materials.color(m, 2), cosViewHalf) * l.irradianceB;
    }

    /** A conductor's Fresnel factor, one channel: Schlick's with F0 = its colour. */
    public static double conductorFresnel(double f0, double cosTheta) {
        return Optics.schlick(f0, cosTheta);
    }

    /**
     * The fraction a smooth dielectric boundary reflects (eta = n_incident / n_transmitted): the
     * exact Fresnel equations or Schlick's approximation; 1 past the critical angle.
     */
    public static double dielectricReflectance(double cosIncident, double eta, boolean exact) {
        return exact ? Optics.fresnelDielectric(cosIncident, eta) : Optics.schlickDielectric(cosIncident, eta);
    }

    /** The ratio of indices a ray meets at a dielectric: n_incident / n_transmitted. */
    public static double eta(double ior, boolean entering) {
        return entering ? 1 / ior : ior;
    }

    /**
     * The phong highlight's cosine: r.v with r the light direction mirrored about n and v = -d
     * (raise it to the shininess where positive).
     */
    public static double phongCosReflectView(Surface s, LightSample l, double cosLight, double dx, double dy,
                                             double dz) {
        double k = 2 * cosLight;
        return -((k * s.nx - l.dirX) * dx + (k * s.ny - l.dirY) * dy + (k * s.nz - l.dirZ) * dz);
    }
}
