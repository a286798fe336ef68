package glint.ui;

import glint.config.Config;
import glint.input.InputException;
import glint.render.FrameBuffer;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Tracer;
import glint.scene.Scene;
import glint.scene.SceneLoader;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;

/**
 * What a still pass of the window costs against the same sample pass headless, measured in one process
 * so that a shared machine's load falls on both alike: passes alternate, headless ({@link Tracer#renderPass}
 * into a frame buffer) and the window's ({@link FrameRenderer#renderPass}: the same pass, then adding it to
 * the average and encoding it), each timed; painting on the screen is not part of it. Usage:
 * {@code java -cp target/glint.jar glint.ui.PassCost [WIDTH HEIGHT [SCENE [PASSES]]]}.
 */
public final class PassCost {

    private PassCost() {
    }

    public static void main(String[] args) throws InputException {
        int width = args.length > 1 ? Integer.parseInt(args[0]) : 800;
        int height = args.length > 1 ? Integer.parseInt(args[1]) : 600;
        Path scenePath = Path.of(args.length > 2 ? args[2] : "scenes/default.yaml");
        int passes = args.length > 3 ? Integer.parseInt(args[3]) : 80;
        Config config = Config.defaults().withSize(width, height).withSamples(1024);
        Scene scene = SceneLoader.load(scenePath);
        RenderScene compiled = RenderScene.compile(scene, RenderSettings.of(config));
        int threads = config.effectiveThreads();
        double[] headless = new double[passes];
        double[] window = new double[passes];
        FrameBuffer frame = new FrameBuffer(width, height);
        try (Tracer tracer = new Tracer(threads); FrameRenderer renderer = new FrameRenderer(threads, 8)) {
            for (int i = 0; i < passes + 20; i++) { // the first 20 of each warm the JIT up
                long t0 = System.nanoTime();
                tracer.renderPass(compiled, frame, config.samples(), i, config.screenDivider());
                long t1 = System.nanoTime();
                renderer.renderPass(compiled, width, height, config.samples(), i);
                long t2 = System.nanoTime();
                if (i >= 20) {
                    headless[i - 20] = (t1 - t0) / 1e6;
                    window[i - 20] = (t2 - t1) / 1e6;
                }
            }
        }
        double h = median(headless);
        double w = median(window);
        System.out.printf(Locale.ROOT, "%dx%d, %d threads, %d passes each: headless pass %.1f ms, window pass %.1f ms"
                + " (median): %.2f x%n", width, height, threads, passes, h, w, w / h);
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }
}
