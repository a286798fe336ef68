package glint.render;

/**
 * Where a pixel's samples go: the centre for one sample; otherwise one jittered point in each cell
 * of a sqrt(n) x sqrt(n) grid. The jitter is a pure function of (pixel, frame, sample), so the image
 * does not depend on threads or tiles.
 */
public final class SamplePattern {

    private static final double INV_2_24 = 1.0 / (1 << 24);

    private SamplePattern() {
    }

    /** A 64-bit hash of the pixel, frame and sample index (SplitMix64 finaliser). */
    static long hash(int pixelIndex, int frame, int sample) {
        long z = (pixelIndex * 0x9E3779B97F4A7C15L) ^ ((long) frame << 32) ^ (sample * 0xBF58476D1CE4E5B9L);
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    /**
     * A uniform number in [0, 1) for the {@code draw}-th random decision of the path of camera ray
     * (pixel, frame, sample): a pure function of the four, independent of the jitter's numbers.
     */
    static double pathUniform(int pixelIndex, int frame, int sample, int draw) {
        long z = hash(pixelIndex, frame, sample) + (draw + 1L) * 0xD1B54A32D192ED03L;
        z = (z ^ (z >>> 32)) * 0xD6E8FEB86659FD93L;
        z = (z ^ (z >>> 32)) * 0xD6E8FEB86659FD93L;
        z ^= z >>> 32;
        return (z >>> 11) * 0x1.0p-53;
    }

    /** The first jitter coordinate in [0, 1) from a hash. */
    static double jitterU(long hash) {
        return (hash >>> 40) * INV_2_24;
    }

    /** The second jitter coordinate in [0, 1) from a hash. */
    static double jitterV(long hash) {
        return ((hash >>> 16) & 0xFFFFFF) * INV_2_24;
    }
}
