package glint.shading;

/** Scratch value: a direction a BSDF sampled at a surface (world space) and what light along it counts for. */
public final class BsdfSample {

    /** The sampled unit direction wi, away from the surface. */
    public double wiX, wiY, wiZ;
    /** f |cos| / pdf per channel: what the radiance arriving along wi is multiplied by; a delta lobe's factor. */
    public double weightR, weightG, weightB;
    /** The density of wi per unit solid angle; 0 for a delta lobe, which has none. */
    public double pdf;
    /** The kind of lobe that chose wi: one of {@link Lobe}'s bits. */
    public int lobe;

    /** Scratch of the BSDFs' sampling: the surface's local basis and a sampled microfacet normal. */
    final ShadingFrame frame = new ShadingFrame();
    final double[] half = new double[3];

    /** Whether wi was chosen by a delta lobe (a mirror, smooth glass): no light sample could find it. */
    public boolean delta() {
        return (lobe & Lobe.SPECULAR) != 0;
    }

    /** Whether wi leaves through the surface (refracted) rather than on the side the light came from. */
    public boolean transmitted() {
        return (lobe & Lobe.TRANSMISSION) != 0;
    }

    void setWeight(double r, double g, double b) {
        weightR = r;
        weightG = g;
        weightB = b;
    }
}
