package glint.bench;

import glint.input.InputException;
import glint.render.FrameBuffer;
import glint.render.PlainTracer;
import glint.render.RenderScene;
import glint.render.Tracer;
import glint.scene.SceneLoader;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;

/**
 * Glint against {@link PlainTracer} in one JVM, frame for frame: after both are warmed up, pairs of
 * frames, one of each, the order swapped from pair to pair, and the ratio of the two frames' times
 * in each pair. On a host whose speed changes from one second to the next, two frames rendered
 * back to back see the same host, so the ratio's median holds still where either tracer's own frame
 * times do not. Checks first that both render the same image. 800x600, 1 sample per pixel, depth 5,
 * cook-torrance, the shipped {@code min_weight} and epsilon.
 *
 * <p>Usage, from the repository root: {@code java -cp target/benchmarks.jar glint.bench.PairedFrames
 * [scene.yaml] [threads] [pairs]} (default scenes/default.yaml, 2 threads, 200 pairs).
 */
public final class PairedFrames {

    static final int WIDTH = 800, HEIGHT = 600, WARM_UP_PAIRS = 40;
    /** How far a pixel's channels may differ: in linear radiance, relative where brighter than 1. */
    public static final double TOLERANCE = 1e-4;

    private PairedFrames() {
    }

    public static void main(String[] args) {
        try {
            Path scenePath = Path.of(args.length > 0 ? args[0] : "scenes/default.yaml");
            int threads = args.length > 1 ? positive("threads", args[1]) : 2;
            int pairs = args.length > 2 ? positive("pairs", args[2]) : 200;
            System.exit(run(scenePath, threads, pairs));
        } catch (InputException | IllegalArgumentException e) {
            System.err.println("error: " + e.getMessage());
            System.err.println("usage: java -cp target/benchmarks.jar glint.bench.PairedFrames [scene.yaml] [threads] [pairs]");
            System.exit(2);
        }
    }

    private static int positive(String name, String text) {
        try {
            int value = Integer.parseInt(text);
            if (value > 0) {
                return value;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new IllegalArgumentException(name + " must be a positive whole number, got '" + text + "'");
    }

    /** Checks the two images, times the pairs and prints the summary; returns the exit status. */
    private static int run(Path scenePath, int threads, int pairs) throws InputException {
        RenderScene scene = RenderScene.compile(SceneLoader.load(scenePath), BenchScenes.SETTINGS);
        FrameBuffer glintFrame = new FrameBuffer(WIDTH, HEIGHT), plainFrame = new FrameBuffer(WIDTH, HEIGHT);
        try (Tracer glint = new Tracer(threads); PlainTracer plain = new PlainTracer(scene, threads)) {
            glint.render(scene, glintFrame, 1, 0, 8);
            plain.render(plainFrame);
            int differing = differingPixels(glintFrame, plainFrame);
            System.out.printf(Locale.ROOT, "%s, threads=%d: %d of %d pixels differ by more than %.0e%n",
                    scenePath, threads, differing, WIDTH * HEIGHT, TOLERANCE);
            if (differing > 0) {
                System.out.println("the two tracers do not render the same image: no timing");
                return 1;
            }
            timePairs(glint, plain, scene, glintFrame, plainFrame, WARM_UP_PAIRS);
            long[][] times = timePairs(glint, plain, scene, glintFrame, plainFrame, pairs);
            System.out.println(summary(times[0], times[1]) + " (after " + WARM_UP_PAIRS + " pairs of warm-up)");
            return 0;
        }
    }

    /**
     * Pixels of two frames of one size with a channel that differs by more than {@link #TOLERANCE}
     * (NaN counts as differing). The tracers agree to far less where they agree at all: they differ
     * only in rounding, as where Glint follows a ray inside an empty glass sphere by its chords.
     */
    public static int differingPixels(FrameBuffer a, FrameBuffer b) {
        float[] x = a.rgb(), y = b.rgb();
        int differing = 0;
        for (int i = 0; i < x.length; i += 3) {
            boolean differs = false;
            for (int c = i; c < i + 3; c++) {
                differs |= !(Math.abs(x[c] - y[c]) <= TOLERANCE * Math.max(1, Math.abs(x[c])));
            }
            differing += differs ? 1 : 0;
        }
        return differing;
    }

    /** Renders {@code pairs} pairs of frames; returns the wall-clock ns of each, [glint, plain][pair]. */
    private static long[][] timePairs(Tracer glint, PlainTracer plain, RenderScene scene, FrameBuffer glintFrame,
                                      FrameBuffer plainFrame, int pairs) {
        long[] glintNanos = new long[pairs], plainNanos = new long[pairs];
        for (int pair = 0; pair < pairs; pair++) {
            if (pair % 2 == 0) {
                glintNanos[pair] = timeGlint(glint, scene, glintFrame);
                plainNanos[pair] = timePlain(plain, plainFrame);
            } else {
                plainNanos[pair] = timePlain(plain, plainFrame);
                glintNanos[pair] = timeGlint(glint, scene, glintFrame);
            }
        }
        return new long[][] {glintNanos, plainNanos};
    }

    private static long timeGlint(Tracer glint, RenderScene scene, FrameBuffer frame) {
        long start = System.nanoTime();
        glint.render(scene, frame, 1, 0, 8);
        return System.nanoTime() - start;
    }

    private static long timePlain(PlainTracer plain, FrameBuffer frame) {
        long start = System.nanoTime();
        plain.render(frame);
        return System.nanoTime() - start;
    }

    /** The summary line: each tracer's median frame and the quartiles of the pairs' ratios plain / glint. */
    static String summary(long[] glintNanos, long[] plainNanos) {
        double[] ratios = new double[glintNanos.length];
        for (int i = 0; i < ratios.length; i++) {
            ratios[i] = (double) plainNanos[i] / glintNanos[i];
        }
        return String.format(Locale.ROOT,
                "paired: pairs=%d glint_median_ms=%.2f plain_median_ms=%.2f ratio_median=%.3f ratio_q1=%.3f ratio_q3=%.3f",
                ratios.length, quantile(toDoubles(glintNanos), 0.5) / 1e6, quantile(toDoubles(plainNanos), 0.5) / 1e6,
                quantile(ratios, 0.5), quantile(ratios, 0.25), quantile(ratios, 0.75));
    }

    private static double[] toDoubles(long[] values) {
        return Arrays.stream(values).asDoubleStream().toArray();
    }

    /** The q-quantile of the values, interpolated between the two nearest ranks. */
    static double quantile(double[] values, double q) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        double rank = q * (sorted.length - 1);
        int below = (int) Math.floor(rank);
        int above = Math.min(below + 1, sorted.length - 1);
        return sorted[below] + (rank - below) * (sorted[above] - sorted[below]);
    }
}
