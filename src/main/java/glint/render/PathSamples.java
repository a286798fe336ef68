package glint.render;

/**
 * The random numbers of one camera ray's path: a pure function of (pixel, frame, sample,
 * dimension), so the image does not depend on threads or tiles. Every dimension is stratified over
 * the pixel's {@code samples} (a perfect square n): a pair of dimensions puts one sample in each
 * cell of a sqrt(n) x sqrt(n) grid, a single one in each of n intervals, and each dimension shuffles
 * its cells among the samples by its own permutation, so that dimensions are not correlated (as a
 * padded stratified sampler does). Any prefix of a pixel's samples is a uniform random subset of the
 * cells, so passes of a window that stop part way are unbiased too. One per render thread.
 */
final class PathSamples {

    /**
     * The pair of dimensions of a camera ray's lens point ({@link CameraRows}); the path's own dimensions
     * count up from 0, so no path number shares its permutation.
     */
    static final int LENS = -1;

    private static final double INV_2_26 = 1.0 / (1 << 26);
    private static final long GOLDEN = 0x9E3779B97F4A7C15L;

    private int samples, side, sample;
    /** Seeds the pixel's permutations, the same for all its samples; and the sample's own jitter. */
    private long pixelSeed, sampleSeed;

    /** The pair's two numbers, set by {@link #pair}. */
    double u1, u2;

    /** Starts sample {@code sample} of the {@code samples} of pixel {@code pixelIndex} in frame {@code frame}. */
    void begin(int pixelIndex, int frame, int sample, int samples) {
        this.samples = samples;
        this.side = (int) Math.round(Math.sqrt(samples));
        this.sample = sample;
        pixelSeed = SamplePattern.hash(pixelIndex, frame, -1);
        sampleSeed = SamplePattern.hash(pixelIndex, frame, sample);
    }

    /** Sets {@link #u1} and {@link #u2} in [0, 1) for the pair of dimensions {@code dimension}. */
    void pair(int dimension) {
        int cell = permute(sample, samples, mix(pixelSeed + dimension * GOLDEN));
        long jitter = mix(sampleSeed + dimension * GOLDEN);
        u1 = (cell % side + ((jitter >>> 38) * INV_2_26)) / side;
        u2 = (cell / side + (((jitter >>> 12) & 0x3FFFFFF) * INV_2_26)) / side;
    }

    /** A number in [0, 1) for the single dimension {@code dimension}. */
    double single(int dimension) {
        int cell = permute(sample, samples, mix(pixelSeed + dimension * GOLDEN));
        long jitter = mix(sampleSeed + dimension * GOLDEN);
        return (cell + (jitter >>> 11) * 0x1.0p-53) / samples;
    }

    /** SplitMix64's finaliser. */
    static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    /**
     * The image of {@code index} under a pseudo-random permutation of [0, n) chosen by {@code seed}:
     * a bijection of the bits below n's next power of two (xor, odd multiplications and xor-shifts,
     * each invertible), applied again while the result lies outside [0, n) (cycle walking).
     */
    static int permute(int index, int n, long seed) {
        if (n <= 1) {
            return 0;
        }
        int bits = 32 - Integer.numberOfLeadingZeros(n - 1);
        int mask = (1 << bits) - 1;
        int shift = Math.max(1, bits / 2);
        int xor = (int) seed & mask, add = (int) (seed >>> 32) & mask;
        int multiplier = (int) (seed >>> 20) | 1;
        int x = index;
        do {
            x ^= xor;
            x = (x * multiplier) & mask;
            x ^= x >>> shift;
            x = (x + add) & mask;
            x = (x * 0x2C1B3C6D) & mask;
            x ^= x >>> shift;
        } while (x >= n);
        return x;
    }
}
