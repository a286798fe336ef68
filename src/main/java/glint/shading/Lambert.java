package glint.shading;

/** A matte surface: Lambert's f = albedo / pi, sampled by the cosine. */
public final class Lambert implements Bsdf {

    private static final double INV_PI = 1 / Math.PI;

    @Override
    public void evaluate(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY,
                         double wiZ, Rgb f) {
        int material = s.material;
        if (wiX * s.nx + wiY * s.ny + wiZ * s.nz > 0) {
            f.set(m.color(material, 0) * INV_PI, m.color(material, 1) * INV_PI, m.color(material, 2) * INV_PI);
        } else {
            f.set(0, 0, 0);
        }
    }

    @Override
    public double pdf(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY,
                      double wiZ) {
        return Math.max(0, wiX * s.nx + wiY * s.ny + wiZ * s.nz) * INV_PI;
    }

    /** A cosine-weighted direction on the normal's side (Malley's method): the weight is the albedo. */
    @Override
    public boolean sample(Materials m, Surface s, double woX, double woY, double woZ, double u1, double u2,
                          double uLobe, BsdfSample out) {
        double r = Math.sqrt(u1), phi = 2 * Math.PI * u2;
        double x = r * Math.cos(phi), y = r * Math.sin(phi), z = Math.sqrt(Math.max(0, 1 - u1));
        if (!(z > 0)) {
            return false;
        }
        ShadingFrame frame = out.frame;
        frame.set(s.nx, s.ny, s.nz);
        out.wiX = frame.worldX(x, y, z);
        out.wiY = frame.worldY(x, y, z);
        out.wiZ = frame.worldZ(x, y, z);
        out.pdf = z * INV_PI;
        int material = s.material;
        out.setWeight(m.color(material, 0), m.color(material, 1), m.color(material, 2));
        out.lobe = Lobe.DIFFUSE_REFLECTION;
        return true;
    }

    @Override
    public int lobes(Materials m, int material) {
        return Lobe.DIFFUSE_REFLECTION;
    }
}
