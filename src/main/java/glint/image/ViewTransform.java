package glint.image;

import java.util.List;
import java.util.Locale;

/**
 * What turns the linear frame into the 8-bit image that is seen (the window, a PNG, a screenshot; a PFM keeps
 * the linear values): an exposure in stops, which multiplies every value by 2^stops, then a tone curve, then
 * the sRGB transfer function, then the dither ({@link Dither}). The curves (docs/conventions.md, "From the
 * frame to the picture"):
 * <ul>
 * <li>{@link Tone#STANDARD}: each channel clamped to [0, 1]; what is brighter than white is white.</li>
 * <li>{@link Tone#NEUTRAL}: the Khronos PBR Neutral tone mapper (Khronos Group, 2024): a small toe (the
 * darkest channel, up to 0.04, taken off all three), then, where the brightest channel passes 0.76, all three
 * scaled by one factor that takes it smoothly towards 1 (never reached), and the colour mixed towards white by
 * as much as it was compressed. One factor for the three channels keeps the hue; the mix to white is how a
 * very bright colour looks.</li>
 * </ul>
 *
 * @param exposure stops: each one doubles the linear values
 * @param tone     the curve after the exposure
 */
public record ViewTransform(double exposure, Tone tone) {

    /** The tone curves, by the name the config, a scene's render: block and --tone use. */
    public enum Tone {
        STANDARD("standard"), NEUTRAL("neutral");

        /** The names, in the order of the enum. */
        public static final List<String> KEYS = List.of("standard", "neutral");

        private final String key;

        Tone(String key) {
            this.key = key;
        }

        public String key() {
            return key;
        }

        /** The curve of that name, or null. */
        public static Tone byKey(String key) {
            for (Tone t : values()) {
                if (t.key.equals(key)) {
                    return t;
                }
            }
            return null;
        }

        /** The other curve, for the window's key. */
        public Tone other() {
            return values()[(ordinal() + 1) % values().length];
        }
    }

    /** The most stops either way. */
    public static final double MAX_EXPOSURE = 16;
    /** Today's image: no exposure, clamped. */
    public static final ViewTransform STANDARD = new ViewTransform(0, Tone.STANDARD);
    /** The default view transform. */
    public static final ViewTransform DEFAULT = new ViewTransform(0, Tone.NEUTRAL);

    public ViewTransform {
        if (!(Math.abs(exposure) <= MAX_EXPOSURE)) {
            throw new IllegalArgumentException("exposure must lie in [-16, 16] stops, got " + exposure);
        }
        if (tone == null) {
            throw new IllegalArgumentException("a view transform needs a tone curve");
        }
    }

    /** This transform with another exposure. */
    public ViewTransform withExposure(double stops) {
        return new ViewTransform(stops, tone);
    }

    /** This transform with another curve. */
    public ViewTransform withTone(Tone curve) {
        return new ViewTransform(exposure, curve);
    }

    /** Whether it leaves the linear values as they are before the clamp (exposure 0, standard): the plain encoding. */
    public boolean isIdentity() {
        return exposure == 0 && tone == Tone.STANDARD;
    }

    /** The factor the exposure multiplies by: 2^exposure. */
    public double scale() {
        return Math.pow(2, exposure);
    }

    /** How the overlay writes it: {@code exposure +1.5  tone neutral}. */
    public String describe() {
        return "exposure " + stops(exposure) + "  tone " + tone.key();
    }

    /** Stops as written for people: {@code 0}, {@code +1.5}, {@code -2}. */
    public static String stops(double stops) {
        String number = stops == Math.rint(stops) ? Long.toString((long) Math.abs(stops))
                : String.format(Locale.ROOT, "%s", Math.abs(stops)).replaceAll("0+$", "");
        return stops > 0 ? "+" + number : stops < 0 ? "-" + number : "0";
    }

    /**
     * A pixel's 8-bit codes, 0xRRGGBB, from its linear red, green and blue: each channel's display value
     * ({@link #display}) encoded and dithered at the pixel's levels ({@link Dither#levels}).
     */
    public int pixel(float r, float g, float b, int levels, double[] scratch) {
        display(r, g, b, scratch);
        return code(scratch[0], Dither.channel(levels, 0)) << 16 | code(scratch[1], Dither.channel(levels, 1)) << 8
                | code(scratch[2], Dither.channel(levels, 2));
    }

    /** The 8-bit code of an sRGB-encoded value in [0, 1] at a dither level. */
    private static int code(double encoded, int level) {
        return Math.min(255, (int) (encoded * 255 + Dither.offset(level)));
    }

    /**
     * The sRGB-encoded display values in [0, 1] of a pixel's linear red, green and blue, into {@code out}. The
     * standard curve's value is {@code Srgb.encode} of the exposed value as a float (so that exposure 0 gives
     * exactly the plain encoding of the frame's floats).
     */
    public void display(float r, float g, float b, double[] out) {
        if (tone == Tone.STANDARD) {
            out[0] = Srgb.encode(exposed(r));
            out[1] = Srgb.encode(exposed(g));
            out[2] = Srgb.encode(exposed(b));
            return;
        }
        double k = scale();
        Neutral.display(positive(r) * k, positive(g) * k, positive(b) * k, out);
    }

    /** A linear value times the exposure's factor, as the float the standard curve clamps and encodes. */
    public float exposed(float linear) {
        return exposure == 0 ? linear : (float) (linear * scale());
    }

    private static double positive(float v) {
        return v > 0 ? v : 0; // also NaN to 0
    }

    /** Khronos PBR Neutral, from linear values (exposed) to encoded display values. */
    static final class Neutral {

        /** Where the compression starts: the brightest channel past 0.76 (after the toe). */
        static final double START = 0.8 - 0.04;
        /** How fast a compressed colour goes to white. */
        static final double DESATURATION = 0.15;

        private Neutral() {
        }

        static void display(double r, double g, double b, double[] out) {
            linear(r, g, b, out);
            out[0] = Srgb.encode(out[0]);
            out[1] = Srgb.encode(out[1]);
            out[2] = Srgb.encode(out[2]);
        }

        /** The curve's linear display values, in [0, 1), into {@code out}. */
        static void linear(double r, double g, double b, double[] out) {
            double x = Math.min(r, Math.min(g, b));
            double offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
            r -= offset;
            g -= offset;
            b -= offset;
            double peak = Math.max(r, Math.max(g, b));
            if (peak >= START) {
                double d = 1 - START;
                double newPeak = 1 - d * d / (peak + d - START);
                double k = newPeak / peak;
                r *= k;
                g *= k;
                b *= k;
                double w = 1 - 1 / (DESATURATION * (peak - newPeak) + 1);
                r += (newPeak - r) * w;
                g += (newPeak - g) * w;
                b += (newPeak - b) * w;
            }
            out[0] = r;
            out[1] = g;
            out[2] = b;
        }
    }
}
