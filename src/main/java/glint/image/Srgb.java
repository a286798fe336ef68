package glint.image;

/** The sRGB transfer function of IEC 61966-2-1, from linear [0, 1] to 8-bit codes. */
public final class Srgb {

    private Srgb() {
    }

    /** The sRGB-encoded value of a linear one, both in [0, 1]; input outside is clamped first. */
    public static double encode(double linear) {
        double c = Math.min(1, Math.max(0, linear));
        if (!(c == c)) {
            c = 0; // NaN never reaches a pixel as anything but black
        }
        return c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
    }

    /**
     * The 8-bit code of a linear value dithered at {@code level} ({@link Dither}): encode, add the level's
     * offset in (0, 1) to the value in code units, cut to a whole code; one of the two codes around it.
     */
    public static int to8Bit(double linear, int level) {
        return Math.min(255, (int) (encode(linear) * 255 + Dither.offset(level)));
    }

    /** The 8-bit code of a linear value: encode, then round to the nearest of 0..255. */
    public static int to8Bit(double linear) {
        return (int) Math.round(encode(linear) * 255);
    }
}
