package glint.shading;

/**
 * The kinds of lobe a BSDF has (as pbrt-v4's BxDFFlags): reflection or transmission, each specular
 * (a delta: one direction, no density), glossy or diffuse. One bit per kind, so a material's lobes
 * ({@link Bsdf#lobes}, kept by {@link Materials#lobes}) are the union of its kinds' bits and a sample's
 * lobe ({@link BsdfSample#lobe}) is one of them; the masks below ask of either.
 */
public final class Lobe {

    public static final int DIFFUSE_REFLECTION = 1;
    public static final int GLOSSY_REFLECTION = 1 << 1;
    public static final int SPECULAR_REFLECTION = 1 << 2;
    public static final int DIFFUSE_TRANSMISSION = 1 << 3;
    public static final int GLOSSY_TRANSMISSION = 1 << 4;
    public static final int SPECULAR_TRANSMISSION = 1 << 5;

    /** Light sent back on the side it came from. */
    public static final int REFLECTION = DIFFUSE_REFLECTION | GLOSSY_REFLECTION | SPECULAR_REFLECTION;
    /** Light sent through the surface. */
    public static final int TRANSMISSION = DIFFUSE_TRANSMISSION | GLOSSY_TRANSMISSION | SPECULAR_TRANSMISSION;
    /** Delta lobes: a mirror, smooth glass. No light sample can find their direction. */
    public static final int SPECULAR = SPECULAR_REFLECTION | SPECULAR_TRANSMISSION;
    public static final int DIFFUSE = DIFFUSE_REFLECTION | DIFFUSE_TRANSMISSION;
    /** Lobes with a density, which f and the pdf describe and a light sample can find. */
    public static final int NON_DELTA = (REFLECTION | TRANSMISSION) & ~SPECULAR;

    private Lobe() {
    }

    /** Whether every lobe of {@code lobes} is a delta (true for none at all). */
    public static boolean allDelta(int lobes) {
        return (lobes & NON_DELTA) == 0;
    }

    /** Whether {@code lobes} has a lobe that is not a delta and sends light through the surface (rough glass). */
    public static boolean transmitsNonDelta(int lobes) {
        return (lobes & NON_DELTA & TRANSMISSION) != 0;
    }

    /** Whether {@code lobes} has a lobe that is not a delta and sends light back on the incoming side. */
    public static boolean reflectsNonDelta(int lobes) {
        return (lobes & NON_DELTA & REFLECTION) != 0;
    }
}
