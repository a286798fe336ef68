package glint.shading;

/**
 * Scratch value: light leaving a light, as its sampler chose it (world space): a ray's origin and unit
 * direction, the flux it stands for (the radiance along it times its cosine at the light, over the
 * densities of its origin and direction), and those densities. What a path starting at a light (a
 * bidirectional integrator's light subpath) begins with.
 */
public final class LightRay {

    /** Where the ray leaves: a point on the light, or on a disc across the scene for a light at infinity. */
    public double originX, originY, originZ;
    /** The unit direction it leaves along. */
    public double dirX, dirY, dirZ;
    /** The flux the ray stands for, per channel: radiance x cosine / (pdfOrigin x pdfDirection). */
    public double fluxR, fluxG, fluxB;
    /** The density of the origin per unit area; 1 for a point light's, which has one point. */
    public double pdfOrigin;
    /** The density of the direction per unit solid angle; 1 for a directional light's, which has one. */
    public double pdfDirection;
    /**
     * The light's unit normal at the origin, for a light with a surface (a sphere light's, outwards);
     * 0 for a point and for a light at infinity, whose origin is on no surface.
     */
    public double normalX, normalY, normalZ;

    /** Scratch of the samplers: a point or a direction, a direction towards a light at infinity, a basis. */
    final double[] scratch = new double[3];
    final LightSample towards = new LightSample();
    final ShadingFrame frame = new ShadingFrame();

    void setOrigin(double x, double y, double z) {
        originX = x;
        originY = y;
        originZ = z;
    }

    void setDirection(double x, double y, double z) {
        dirX = x;
        dirY = y;
        dirZ = z;
    }

    void setNormal(double x, double y, double z) {
        normalX = x;
        normalY = y;
        normalZ = z;
    }

    void setFlux(double r, double g, double b) {
        fluxR = r;
        fluxG = g;
        fluxB = b;
    }
}
