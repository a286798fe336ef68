package glint.ui.frames;

import glint.config.Config;
import glint.image.FrameBuffer;
import glint.input.InputException;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Tracer;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;

/**
 * What a still pass of the window costs against a headless sample pass, measured in one process so that a
 * shared machine's load falls on both alike. Rounds alternate: a headless still of 16 samples per pixel
 * ({@link Tracer#render}, its time divided by 16: the yardstick of docs/window.md), then 16 window passes
 * one at a time ({@link FrameRenderer#renderPass}: each traced, added to the average and encoded), then 16
 * window passes as the window traces them ({@link RefinePacing} at the default target_fps, 30: quick passes
 * several in one go); painting on the screen is not part of it. Usage:
 * {@code java -cp target/benchmarks.jar glint.ui.frames.PassCost [WIDTH HEIGHT [SCENE [ROUNDS]]]}.
 */
public final class PassCost {

    private PassCost() {
    }

    public static void main(String[] args) throws InputException {
        int width = args.length > 1 ? Integer.parseInt(args[0]) : 800;
        int height = args.length > 1 ? Integer.parseInt(args[1]) : 600;
        Path scenePath = Path.of(args.length > 2 ? args[2] : "scenes/default.yaml");
        int rounds = args.length > 3 ? Integer.parseInt(args[3]) : 10;
        int samples = 16;
        Config config = Config.defaults().withSize(width, height).withSamples(samples);
        Scene scene = SceneLoader.load(scenePath);
        RenderScene compiled = RenderScene.compile(scene, config.renderSettings());
        int threads = config.effectiveThreads();
        double[] headless = new double[rounds];
        double[] single = new double[rounds];
        double[] paced = new double[rounds];
        FrameBuffer frame = new FrameBuffer(width, height);
        RefinePacing pacing = new RefinePacing();
        pacing.interval(RefinePacing.windowInterval(config.targetFps()));
        try (Tracer tracer = new Tracer(threads); FrameRenderer renderer = new FrameRenderer(threads, 8)) {
            for (int i = 0; i < rounds + 3; i++) { // the first 3 rounds warm the JIT up
                long t0 = System.nanoTime();
                tracer.render(compiled, frame, samples, 0, config.screenDivider());
                long t1 = System.nanoTime();
                for (int pass = 0; pass < samples; pass++) {
                    renderer.renderPass(compiled, width, height, samples, pass);
                }
                long t2 = System.nanoTime();
                for (int pass = 0; pass < samples; ) {
                    long start = System.nanoTime();
                    int count = pacing.passes(pass, samples, start);
                    renderer.renderPasses(compiled, width, height, samples, pass, count);
                    pass += count;
                    pacing.passesDone(pass, count, samples, start, System.nanoTime(),
                            new ResolutionGovernor.Size(width, height), null);
                }
                long t3 = System.nanoTime();
                if (i >= 3) {
                    headless[i - 3] = (t1 - t0) / 1e6 / samples;
                    single[i - 3] = (t2 - t1) / 1e6 / samples;
                    paced[i - 3] = (t3 - t2) / 1e6 / samples;
                }
            }
        }
        double h = median(headless);
        System.out.printf(Locale.ROOT, "%dx%d, %d threads, %d rounds: headless sample pass %.2f ms; window pass one at a"
                + " time %.2f ms (%.2f x), as the window traces them %.2f ms (%.2f x) (medians)%n", width, height, threads,
                rounds, h, median(single), median(single) / h, median(paced), median(paced) / h);
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }
}
