package glint.render;

import glint.config.Config;
import glint.image.FrameBuffer;
import glint.image.Srgb;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

/**
 * How far a still image at the shipped settings is from the converged image of the same scene, in
 * 8-bit sRGB units over every channel of every pixel. Converged: {@link #CONVERGED_DEPTH} hits and
 * the plain cut-off at {@link #CONVERGED_MIN_WEIGHT}, whose loss no 8-bit image shows; the same
 * samples and jitter, so only pruning and depth differ.
 *
 * <p>The table at any size, for a config, the scenes under a folder and more scene files:
 * {@code java -cp target/classes:target/test-classes:SNAKEYAML_JAR glint.render.StillAccuracy 800 600
 * config.properties scenes src/test/resources/scenes/glass-on-mirror.yaml}; {@code -Dpruning=CUTOFF}
 * measures the plain cut-off instead of the roulette.
 */
final class StillAccuracy {

    static final int CONVERGED_DEPTH = 64;
    static final double CONVERGED_MIN_WEIGHT = 1e-4;

    /** Mean and 99.9th percentile of |shipped - converged| in 8-bit sRGB units, and the render CPU seconds of each. */
    record Result(double mean, double p999, double shippedSeconds, double convergedSeconds) {
    }

    private StillAccuracy() {
    }

    /** Every scene file under {@code folder}, in name order. */
    static List<Path> scenes(Path folder) throws Exception {
        try (Stream<Path> files = Files.walk(folder)) {
            return files.filter(p -> p.toString().endsWith(".yaml")).sorted().toList();
        }
    }

    static Result measure(Scene scene, Config config, int width, int height, int threads) {
        return measure(scene, config, RenderSettings.Pruning.ROULETTE, width, height, threads);
    }

    static Result measure(Scene scene, Config config, RenderSettings.Pruning pruning, int width, int height,
                          int threads) {
        RenderSettings shipped = config.renderSettings().withPruning(pruning);
        RenderSettings converged = new RenderSettings(config.shading(), CONVERGED_DEPTH, CONVERGED_MIN_WEIGHT,
                config.epsilon()).withPruning(RenderSettings.Pruning.CUTOFF);
        FrameBuffer a = new FrameBuffer(width, height);
        FrameBuffer b = new FrameBuffer(width, height);
        double shippedSeconds, convergedSeconds;
        try (Tracer tracer = new Tracer(threads)) {
            tracer.render(RenderScene.compile(scene, shipped), a, config.samples(), 0, config.screenDivider());
            shippedSeconds = tracer.renderCpuNanos() / 1e9;
            tracer.render(RenderScene.compile(scene, converged), b, config.samples(), 0, config.screenDivider());
            convergedSeconds = tracer.renderCpuNanos() / 1e9 - shippedSeconds;
        }
        return compare(a, b, shippedSeconds, convergedSeconds);
    }

    static Result compare(FrameBuffer a, FrameBuffer b, double shippedSeconds, double convergedSeconds) {
        float[] x = a.rgb(), y = b.rgb();
        double[] diff = new double[x.length];
        double sum = 0;
        for (int i = 0; i < x.length; i++) {
            diff[i] = Math.abs(Srgb.to8Bit(x[i]) - Srgb.to8Bit(y[i]));
            sum += diff[i];
        }
        Arrays.sort(diff);
        double p999 = diff[Math.min(diff.length - 1, (int) Math.ceil(0.999 * diff.length) - 1)];
        return new Result(sum / diff.length, p999, shippedSeconds, convergedSeconds);
    }

    public static void main(String[] args) throws Exception {
        int width = Integer.parseInt(args[0]), height = Integer.parseInt(args[1]);
        Config config = args.length > 2 ? glint.config.ConfigLoader.load(Path.of(args[2])) : Config.defaults();
        String folder = args.length > 3 ? args[3] : "scenes";
        System.out.printf(Locale.ROOT, "%d x %d, %d spp, depth %d, min_weight %s%n", width, height,
                config.samples(), config.recursionMax(), config.minWeight());
        List<Path> files = new java.util.ArrayList<>(scenes(Path.of(folder)));
        for (int i = 4; i < args.length; i++) {
            files.add(Path.of(args[i]));
        }
        RenderSettings.Pruning pruning = RenderSettings.Pruning.valueOf(System.getProperty("pruning", "ROULETTE"));
        measure(SceneLoader.load(files.get(0)), config, pruning, width, height, 2); // untimed: the JIT compiles
        for (Path file : files) {
            Result r = measure(SceneLoader.load(file), config, pruning, width, height, 2);
            System.out.printf(Locale.ROOT, "| %s | %.3f | %.0f | %.2f | %.2f |%n", file, r.mean(), r.p999(),
                    r.shippedSeconds(), r.convergedSeconds());
        }
    }
}
