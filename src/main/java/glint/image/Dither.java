package glint.image;

/**
 * The dither added before a linear value is quantised to 8 bits (PNG and the window), so that a smooth
 * gradient shows no bands: a value between two codes becomes the upper one with the probability of its
 * distance from the lower, and the codes of a region average to its exact value. The offset of a pixel's
 * channel is one of {@link #LEVELS} steps in (0, 1), fixed by the pixel's coordinates and a constant
 * seed, never by the frame, a thread or a tile: the same settings give the same bytes, and every code is
 * within one of plain rounding. A value on a code (within 1/128 of it) keeps that code.
 */
public final class Dither {

    /** The steps an offset takes: (level + 0.5) / LEVELS for levels 0 to LEVELS - 1. */
    public static final int LEVELS = 64;
    private static final int BITS = 6;
    private static final int MASK = LEVELS - 1;
    /** Fixes the pattern: a different seed gives different, equally good noise. */
    private static final int SEED = 0x5bd1e995;

    private Dither() {
    }

    /** The levels of pixel (x, y), red in bits 0-5, green in 6-11, blue in 12-17. */
    public static int levels(int x, int y) {
        int h = x * 0x27d4eb2d ^ Integer.rotateLeft(y * 0x165667b1, 13) ^ SEED;
        h ^= h >>> 16;
        h *= 0x85ebca6b;
        h ^= h >>> 13;
        h *= 0xc2b2ae35;
        h ^= h >>> 16;
        return h;
    }

    /** The level of one channel (0 red, 1 green, 2 blue) in {@link #levels}. */
    public static int channel(int levels, int channel) {
        return levels >>> (BITS * channel) & MASK;
    }

    /** The offset a level adds to a value in code units before it is cut to a whole code. */
    public static double offset(int level) {
        return (level + 0.5) / LEVELS;
    }
}
