package glint.shading;

import glint.math.Vector3d;

/**
 * The surface of a light with a body (a sphere light): black, it sends back nothing and sends on
 * no ray; it sends only the light's radiance, its material's colour, uniformly outwards. Not a
 * material type a scene names: the scene compiler gives each such light's body one ({@link #material}).
 */
public final class LampBody implements Bsdf, WhittedResponse {

    private static final LampBody BODY = new LampBody();

    private LampBody() {
    }

    /**
     * The material of a light's body sending {@code radiance}: its colour, no phong coefficient (ior
     * 1) and no numbers of its own.
     */
    public static Materials.Material material(Vector3d radiance) {
        return new Materials.Material(BODY, BODY, radiance, 0, 0, 0, 0, 1, new double[0]);
    }

    @Override
    public void evaluate(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY,
                         double wiZ, Rgb f) {
        f.set(0, 0, 0);
    }

    @Override
    public double pdf(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY,
                      double wiZ) {
        return 0;
    }

    /** Nothing is scattered: the path ends at the light. */
    @Override
    public boolean sample(Materials m, Surface s, double woX, double woY, double woZ, double u1, double u2,
                          double uLobe, BsdfSample out) {
        return false;
    }

    /** No lobes: no light sample could add anything to black, and the light loop is skipped. */
    @Override
    public int lobes(Materials m, int material) {
        return 0;
    }

    /** To Whitted's models: no single rays on. */
    @Override
    public void specular(Materials m, Surface s, SingleRays out) {
        out.setReflect(0, 0, 0);
        out.setTransmit(0, 0, 0);
    }

    @Override
    public boolean emits() {
        return true;
    }

    /** The light's radiance, the same towards every direction outside it; none inside it. */
    @Override
    public void emitted(Materials m, Surface s, Rgb out) {
        int material = s.material;
        if (s.front) {
            out.set(m.color(material, 0), m.color(material, 1), m.color(material, 2));
        } else {
            out.set(0, 0, 0);
        }
    }
}
