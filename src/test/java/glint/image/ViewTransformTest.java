package glint.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.ViewTransform.Tone;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The view transform's curves by their values: docs/conventions.md, "From the frame to the picture". */
class ViewTransformTest {

    private static final ViewTransform NEUTRAL = new ViewTransform(0, Tone.NEUTRAL);
    private static final int[] LEVELS = {0, 17, 31, 32, 63};

    private static double[] linearNeutral(double r, double g, double b) {
        double[] out = new double[3];
        ViewTransform.Neutral.linear(r, g, b, out);
        return out;
    }

    private static int code(ViewTransform view, float v, int level) {
        int levels = level | level << 6 | level << 12;
        return view.pixel(v, v, v, levels, new double[3]) & 0xff;
    }

    @Test
    void standardIsTheClampOfTodayCodeForCode() {
        for (int i = -10; i <= 3000; i++) {
            float v = i / 1000f;
            for (int level : LEVELS) {
                assertEquals(Srgb.to8Bit(Math.min(1, Math.max(0, v)), level), code(ViewTransform.STANDARD, v, level),
                        "value " + v + " level " + level);
            }
        }
        assertEquals(255, code(ViewTransform.STANDARD, 1e30f, 0));
        assertEquals(0, code(ViewTransform.STANDARD, Float.NaN, 63));
    }

    @Test
    void eachStopDoublesTheLinearValue() {
        Random random = new Random(7);
        for (Tone tone : Tone.values()) {
            for (int i = 0; i < 2000; i++) {
                float v = (float) Math.pow(2, random.nextDouble() * 16 - 10);
                int stops = random.nextInt(9) - 4;
                float brighter = (float) (v * Math.pow(2, stops)); // a power of two: exact
                for (int level : LEVELS) {
                    assertEquals(code(new ViewTransform(0, tone), brighter, level),
                            code(new ViewTransform(stops, tone), v, level), tone + " " + v + " at " + stops + " stops");
                }
            }
        }
        assertEquals(2.0, new ViewTransform(1, Tone.STANDARD).scale());
        assertEquals(0.25, new ViewTransform(-2, Tone.NEUTRAL).scale());
    }

    @Test
    void blackStaysBlackInBothCurves() {
        for (Tone tone : Tone.values()) {
            for (double stops : new double[] {-16, 0, 16}) {
                assertEquals(0, new ViewTransform(stops, tone).pixel(0f, 0f, 0f, 0x3ffff, new double[3]), tone + " " + stops);
            }
        }
        assertEquals(0, linearNeutral(0, 0, 0)[0]);
    }

    /** Khronos PBR Neutral on greys: the toe takes 0.04 off, the shoulder starts at 0.76 and stays below 1. */
    @Test
    void neutralsValuesWorkedOutByHand() {
        assertEquals(0.18 - 0.04, linearNeutral(0.18, 0.18, 0.18)[0], 1e-15);
        assertEquals(0.5 - 0.04, linearNeutral(0.5, 0.5, 0.5)[0], 1e-15);
        assertEquals(6.25 * 0.05 * 0.05, linearNeutral(0.05, 0.05, 0.05)[1], 1e-15); // the toe: 6.25 x^2 below 0.08
        assertEquals(0.76, linearNeutral(0.8, 0.8, 0.8)[2], 1e-15); // where the shoulder starts
        double d = 0.24, peak = 10 - 0.04;
        assertEquals(1 - d * d / (peak + d - 0.76), linearNeutral(10, 10, 10)[0], 1e-12);
        double huge = linearNeutral(1e30, 1e30, 1e30)[0];
        assertTrue(huge <= 1 && huge > 0.999999, "white is approached, never passed: " + huge);
        assertTrue(linearNeutral(1e4, 1e4, 1e4)[0] < 1, "not reached at 10^4");
        // a colour under the shoulder keeps its channels' differences: the curve is standard's there, less 0.04
        double[] red = linearNeutral(0.6, 0.1, 0.1);
        assertEquals(0.56, red[0], 1e-15);
        assertEquals(0.06, red[1], 1e-15);
    }

    @Test
    void neutralRisesWithTheLightChannelByChannel() {
        double[][] colours = {{1, 1, 1}, {1, 0.77, 0.34}, {0.8, 0.1, 0.1}, {0.1, 0.2, 0.8}, {0, 1, 0}, {0.3, 0.3, 0}};
        for (double[] c : colours) {
            double[] before = linearNeutral(0, 0, 0);
            for (int i = 1; i <= 4000; i++) {
                double k = Math.pow(2, i / 200.0 - 12);
                double[] now = linearNeutral(c[0] * k, c[1] * k, c[2] * k);
                for (int ch = 0; ch < 3; ch++) {
                    assertTrue(now[ch] >= before[ch] - 1e-15, "channel " + ch + " of " + java.util.Arrays.toString(c)
                            + " falls at " + k + ": " + before[ch] + " -> " + now[ch]);
                    assertTrue(now[ch] >= 0 && now[ch] <= 1, "in [0, 1]: " + now[ch]);
                }
                before = now;
            }
        }
    }

    /** The hue of a colour (where it lies between its channels) is kept, however bright: only its saturation goes. */
    @Test
    void neutralKeepsTheHue() {
        Random random = new Random(11);
        for (int i = 0; i < 10000; i++) {
            double k = Math.pow(2, random.nextDouble() * 12 - 4);
            double r = random.nextDouble() * k, g = random.nextDouble() * k, b = random.nextDouble() * k;
            double[] out = linearNeutral(r, g, b);
            double spread = Math.max(r, Math.max(g, b)) - Math.min(r, Math.min(g, b));
            double outSpread = Math.max(out[0], Math.max(out[1], out[2])) - Math.min(out[0], Math.min(out[1], out[2]));
            if (spread < 1e-6 * k || outSpread < 1e-9) {
                continue;
            }
            for (int ch = 0; ch < 3; ch++) { // each channel's place between the smallest and the largest
                double place = (new double[] {r, g, b}[ch] - Math.min(r, Math.min(g, b))) / spread;
                double outPlace = (out[ch] - Math.min(out[0], Math.min(out[1], out[2]))) / outSpread;
                assertEquals(place, outPlace, 1e-6, "channel " + ch + " of " + r + ", " + g + ", " + b);
            }
        }
    }

    @Test
    void stopsAreWrittenForPeople() {
        assertEquals("0", ViewTransform.stops(0));
        assertEquals("+1", ViewTransform.stops(1));
        assertEquals("-1.5", ViewTransform.stops(-1.5));
        assertEquals("+0.25", ViewTransform.stops(0.25));
        assertEquals("exposure +2  tone standard", new ViewTransform(2, Tone.STANDARD).describe());
    }
}
