package glint.render;

import glint.shading.Surface;

/**
 * One vertex of a bidirectional path ({@link BdptIntegrator}), of the subpath from the camera or from
 * a light: where it is, the throughput of the subpath up to it, and the two densities (per unit area
 * where it is a point, per solid angle where it is a direction at infinity) with which it is reached
 * from either end, which the multiple importance sampling weights are made of (Veach 1997, 10.2).
 * The integrator keeps a fixed array of them per subpath and refills them for every path.
 */
final class BdptVertex {

    /** The camera's point (the eye, or a point of the lens). */
    static final int CAMERA = 0;
    /** A point of a light (a point light, a sphere light's surface), or a light's body a camera path met. */
    static final int LIGHT = 1;
    /** A surface that scatters: a hit of either subpath. */
    static final int SURFACE = 2;
    /** A direction towards light at infinity (a sun, the sky, a directional light), in {@link #farX} ... */
    static final int FAR = 3;

    int kind;
    /**
     * The point and its normal: for a {@link #SURFACE} the hit as shading sees it (normal facing the ray
     * that arrived); for a {@link #LIGHT} the point in {@code px..pz} and the light's outward normal in
     * {@code nx..nz} (0 for a point light); for the {@link #CAMERA} its point.
     */
    final Surface surface = new Surface();
    /** For a {@link #FAR} vertex: the unit direction from the scene towards the light. */
    double farX, farY, farZ;
    /** For a light's vertex: its number among the lights and the sky (-1: every light at infinity). */
    int light;
    /** The unit direction towards the vertex before it on its own subpath (a {@link #SURFACE}'s). */
    double woX, woY, woZ;
    /** The subpath's throughput up to and including the arrival at this vertex, per channel. */
    double betaR, betaG, betaB;
    /** The density with which its own subpath reached it, and with which the other end's would. */
    double pdfFwd, pdfRev;
    /** Whether the subpath left it by a delta lobe: no other strategy could have made that turn. */
    boolean delta;
    /** Whether it is a point or direction of a delta light (a point light, a directional one). */
    boolean deltaLight;
    /** Whether a path can be joined here by a connecting ray: a surface with a lobe that is not delta. */
    boolean connectible;
    /**
     * Whether paths may be merged here: a surface with a diffuse lobe. A merge weighs the light of another
     * path by the BSDF at a direction that path brought; a glossy lobe turns that into fireflies, where
     * joins and the camera's own sampling serve it better.
     */
    boolean diffuse;

    /** Whether it lies on a surface whose cosine converts densities: a scattering surface or a sphere light. */
    boolean onSurface() {
        return kind == SURFACE || kind == LIGHT && (surface.nx != 0 || surface.ny != 0 || surface.nz != 0);
    }

    void setPoint(double x, double y, double z) {
        surface.px = x;
        surface.py = y;
        surface.pz = z;
    }

    void setNormal(double x, double y, double z) {
        surface.nx = x;
        surface.ny = y;
        surface.nz = z;
    }

    void setFar(double x, double y, double z) {
        farX = x;
        farY = y;
        farZ = z;
    }

    void setBeta(double r, double g, double b) {
        betaR = r;
        betaG = g;
        betaB = b;
    }
}
