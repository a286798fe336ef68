package glint.render;

import glint.image.FrameBuffer;
import java.util.Arrays;

/**
 * Adaptive sampling: the average of a refinement's passes, pixel by pixel, and which pixels still need
 * samples. Passes come in rounds of {@link #ROUND}; at the end of each round every pixel still sampled
 * adds its round's mean luminance to its own statistics, and its noise is estimated from them: the
 * standard error of the pixel's mean luminance (the spread of its round means over the square root of
 * their count) over its mean luminance, the mean taken no darker than {@link #DARKEST}. A pixel whose
 * estimate is below the threshold after at least {@link #MIN_ROUNDS} rounds has converged; it stops
 * receiving samples once every pixel of its 3 x 3 neighbourhood has converged too (Cycles' noise threshold
 * likewise spreads a pixel's "not converged" to its neighbours, so that a lone pixel whose few samples
 * happened to agree does not stop alone). Every pixel stops at the cap.
 *
 * <p>Deterministic: the decisions are made only at the ends of rounds, from the pixels' own values (light
 * that other pixels' paths splat onto them included, as it is part of each pass), so the pixels traced,
 * and each pixel's samples (always the first n of its sequence), do not depend on threads, tiles, or how
 * the passes of a round are split into calls. Ranges of pixels that do not overlap may be added on
 * different threads at once ({@link #add}); {@link #endRound} is called alone.
 */
public final class Convergence {

    /**
     * The passes come in stratified patterns of this many samples (8 x 8): pass p is sample p mod 64 of the
     * pattern of frame p / 64, so any prefix of a pixel's passes is unbiased, and a whole pattern is as good as a
     * still of 64 samples. The window's refinement uses the same. Chosen, not measured.
     */
    public static final int PATTERN = 64;
    /**
     * Passes a round: the noise is estimated from rounds' means, and the pixels that stop do so only at a
     * round's end. 8 divides the window's pattern of 64, so a pattern is 8 rounds.
     */
    public static final int ROUND = 8;
    /**
     * The fewest rounds before a pixel may stop: 8 rounds, 64 samples, a whole stratified 8 x 8 pattern, and
     * a spread estimated from 8 means. Chosen, not measured against other minimums: a pixel stopped early keeps
     * the bias of the rule (one whose few samples met no firefly stops darker than it should).
     */
    public static final int MIN_ROUNDS = 8;
    /**
     * The darkest mean luminance the noise is taken relative to: a pixel darker than this (3 levels of 8-bit
     * sRGB at exposure 0) is judged by its absolute error, so black corners do not need endless samples. Chosen.
     */
    public static final double DARKEST = 1e-3;
    /**
     * The window's threshold where the config sets none ({@code noise=0}): 1 % relative noise a pixel. Measured
     * on the reference scenes at 200 x 150 (docs/accuracy.md, "Adaptive sampling"): 189 (sky-and-sun) to 1018
     * (caustic-lamp) samples a pixel on average, within FLIP 0.006 to 0.033 of the independent renderer's images,
     * as close as uniform sampling at the same render CPU.
     */
    public static final double WINDOW_NOISE = 0.01;

    private final int width, height;
    private double threshold;
    private int cap;
    /** Per pixel: the sum of its passes' colours, and how many passes it has. */
    private final double[] sum;
    private final int[] samples;
    /** Per pixel: its luminance summed over the round under way; the sum and sum of squares of its round means. */
    private final double[] roundLuma, meanSum, meanSquares;
    /** Per pixel: whether it has converged, and whether it is traced in the next pass (read by the tracer). */
    private final boolean[] converged, active;
    private int activePixels;
    private int passes;

    /**
     * A refinement of a width x height image whose pixels stop below {@code threshold} (0: none stops before the
     * cap) or at {@code cap} passes.
     */
    public Convergence(int width, int height, double threshold, int cap) {
        this.width = width;
        this.height = height;
        int n = width * height;
        sum = new double[3 * n];
        samples = new int[n];
        roundLuma = new double[n];
        meanSum = new double[n];
        meanSquares = new double[n];
        converged = new boolean[n];
        active = new boolean[n];
        reset(threshold, cap);
    }

    /** Starts over, with this threshold and cap, keeping the arrays. */
    public void reset(double newThreshold, int newCap) {
        if (!(newThreshold >= 0) || newCap < 1) {
            throw new IllegalArgumentException("threshold " + newThreshold + ", cap " + newCap);
        }
        threshold = newThreshold;
        cap = newCap;
        Arrays.fill(sum, 0);
        Arrays.fill(samples, 0);
        Arrays.fill(roundLuma, 0);
        Arrays.fill(meanSum, 0);
        Arrays.fill(meanSquares, 0);
        Arrays.fill(converged, false);
        Arrays.fill(active, true);
        activePixels = width * height;
        passes = 0;
    }

    /** Bytes a pixel of a refinement holds, for the memory check. */
    public static final long BYTES_PER_PIXEL = 3 * 8 + 4 + 3 * 8 + 2;

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public double threshold() {
        return threshold;
    }

    public int cap() {
        return cap;
    }

    /** The pixels the next pass traces (row by row): the tracer's {@link Tracer#traceOnly} mask. Not to be written. */
    public boolean[] active() {
        return active;
    }

    /** How many pixels the next pass traces. */
    public int activePixels() {
        return activePixels;
    }

    /** Passes done: the most samples a pixel has. */
    public int passes() {
        return passes;
    }

    /** Whether no pixel is traced any more: every one converged, or the cap reached. */
    public boolean done() {
        return activePixels == 0 || passes >= cap;
    }

    /**
     * How many passes the next call may trace from {@code wanted}: never past the cap, nor, where pixels may
     * converge, past a round's end or a pattern's.
     */
    public int inOneCall(int wanted) {
        int left = threshold == 0 ? cap - passes
                : Math.min(ROUND - passes % ROUND, Math.min(PATTERN - passes % PATTERN, cap - passes));
        return Math.max(1, Math.min(wanted, left));
    }

    /**
     * Adds pixels [from, to) of the average of {@code count} passes, traced in one call for the pixels active
     * now, with weight {@code count}; the others are left out. Call {@link #passesAdded} once every range is in.
     */
    public void add(FrameBuffer pass, int count, int from, int to) {
        float[] in = pass.rgb();
        for (int p = from, i = 3 * from; p < to; p++, i += 3) {
            if (!active[p]) {
                continue;
            }
            double r = in[i], g = in[i + 1], b = in[i + 2];
            sum[i] += count * r;
            sum[i + 1] += count * g;
            sum[i + 2] += count * b;
            samples[p] += count;
            roundLuma[p] += count * luma(r, g, b);
        }
    }

    /**
     * {@code count} passes are added for every pixel: at a round's end each active pixel's statistics take the
     * round, its noise is tested, and the pixels that stop are left out from the next pass on.
     */
    public void passesAdded(int count) {
        passes += count;
        if (passes % ROUND == 0) {
            endRound();
        }
        if (passes >= cap) {
            Arrays.fill(active, false);
            activePixels = 0;
        }
    }

    private void endRound() {
        int n = width * height;
        for (int p = 0; p < n; p++) {
            if (!active[p]) {
                continue;
            }
            double mean = roundLuma[p] / ROUND;
            roundLuma[p] = 0;
            meanSum[p] += mean;
            meanSquares[p] += mean * mean;
            converged[p] = threshold > 0 && samples[p] / ROUND >= MIN_ROUNDS && noise(p) < threshold;
        }
        int left = 0;
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int p = y * width + x;
                if (active[p] && !neighbourhoodConverged(x, y)) {
                    left++;
                } else {
                    active[p] = false;
                }
            }
        }
        activePixels = left;
    }

    private boolean neighbourhoodConverged(int x, int y) {
        for (int j = Math.max(0, y - 1), yEnd = Math.min(height - 1, y + 1); j <= yEnd; j++) {
            for (int i = Math.max(0, x - 1), xEnd = Math.min(width - 1, x + 1); i <= xEnd; i++) {
                if (!converged[j * width + i]) {
                    return false;
                }
            }
        }
        return true;
    }

    /** Pixel p's noise estimate: the standard error of its mean luminance over the mean; NaN before 2 rounds. */
    public double noise(int p) {
        int rounds = samples[p] / ROUND;
        if (rounds < 2) {
            return Double.NaN;
        }
        double mean = meanSum[p] / rounds;
        double variance = Math.max(0, (meanSquares[p] - rounds * mean * mean) / (rounds - 1));
        return Math.sqrt(variance / rounds) / Math.max(mean, DARKEST);
    }

    /**
     * The noise left in the image, relative to its brightness (the window's overlay): the root mean square of
     * the pixels' standard errors over their mean luminance. The mean of squares, not of the standard errors
     * themselves: a variance estimated from few rounds is unbiased, its square root is not (it is low by a
     * fifth at 2 rounds), so the figure falls as 1/sqrt(samples) where the noise does. NaN before every pixel
     * has 2 rounds.
     */
    public double relativeNoise() {
        double variances = 0, means = 0;
        for (int p = 0; p < samples.length; p++) {
            int rounds = samples[p] / ROUND;
            if (rounds < 2) {
                return Double.NaN;
            }
            double mean = meanSum[p] / rounds;
            variances += Math.max(0, (meanSquares[p] - rounds * mean * mean) / (rounds - 1)) / rounds;
            means += mean;
        }
        int n = samples.length;
        return means > 0 ? Math.sqrt(variances / n) / (means / n) : Double.NaN;
    }

    /** Samples pixel p has (x + y * width). */
    public int samples(int p) {
        return samples[p];
    }

    /** Samples spent, over every pixel. */
    public long samplesSpent() {
        long total = 0;
        for (int s : samples) {
            total += s;
        }
        return total;
    }

    /** The fewest samples a pixel has. */
    public int fewestSamples() {
        int least = Integer.MAX_VALUE;
        for (int s : samples) {
            least = Math.min(least, s);
        }
        return least;
    }

    /** Sets {@code out} (3 values from {@code at}) to pixel p's average: the sum of its passes over their count. */
    public void average(int p, double[] out, int at) {
        int i = 3 * p;
        double inverse = samples[p] == 0 ? 0 : 1.0 / samples[p];
        out[at] = sum[i] * inverse;
        out[at + 1] = sum[i + 1] * inverse;
        out[at + 2] = sum[i + 2] * inverse;
    }

    /** Writes every pixel's average into {@code frame}, of this size. */
    public void writeAverage(FrameBuffer frame) {
        double[] rgb = new double[3];
        for (int y = 0, p = 0; y < height; y++) {
            for (int x = 0; x < width; x++, p++) {
                average(p, rgb, 0);
                frame.set(x, y, rgb[0], rgb[1], rgb[2]);
            }
        }
    }

    /**
     * Renders every pass the refinement still needs on {@code tracer}, a round in each call, until it is
     * {@link #done}; {@code frame} (of this size) is the tracer's scratch, and {@code afterRound} is told after
     * each round (a progress line). The average is then {@link #writeAverage}'s.
     */
    public void refine(Tracer tracer, RenderScene scene, FrameBuffer frame, int divider, Runnable afterRound) {
        try {
            while (!done()) {
                int count = inOneCall(ROUND);
                tracer.traceOnly(active);
                tracer.renderPasses(scene, frame, PATTERN, passes, count, divider);
                add(frame, count, 0, width * height);
                passesAdded(count);
                afterRound.run();
            }
        } finally {
            tracer.traceOnly(null);
        }
    }

    /** Rec. 709 luminance of linear RGB. */
    static double luma(double r, double g, double b) {
        return 0.2126 * r + 0.7152 * g + 0.0722 * b;
    }
}
