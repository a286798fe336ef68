package glint.app;

import glint.config.Config;
import glint.image.ImageWriter;
import glint.input.InputException;
import glint.render.FrameBuffer;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Tracer;
import glint.scene.Scene;
import glint.scene.SceneLoader;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;

/** The modes without a window: render one still to a file, or time frames (--bench). */
final class Headless {

    private Headless() {
    }

    static int renderStill(Path scenePath, Config config, Path output, PrintWriter out)
            throws InputException, IOException {
        if (!ImageWriter.isSupported(output)) {
            throw new InputException("glint", 0, 0,
                    "--output: expected a file ending in .png or .pfm, got '" + output + "'");
        }
        Path folder = output.toAbsolutePath().getParent();
        if (folder != null && !Files.isDirectory(folder)) {
            throw new InputException("glint", 0, 0, "--output: no such folder '" + folder + "'");
        }
        Scene scene = SceneLoader.load(scenePath, config.limits().scene());
        RenderScene compiled = RenderScene.compile(scene, RenderSettings.of(config));
        FrameBuffer frame = new FrameBuffer(config.displayWidth(), config.displayHeight());
        long start = System.nanoTime();
        try (Tracer tracer = new Tracer(config.effectiveThreads())) {
            tracer.render(compiled, frame, config.samples(), 0, config.screenDivider());
        }
        long elapsed = System.nanoTime() - start;
        ImageWriter.write(frame, output);
        out.printf(Locale.ROOT, "wrote %s (%dx%d, %d spp, %d threads, %s, depth %d) in %.1f ms%n",
                output, frame.width(), frame.height(), config.samples(), config.effectiveThreads(),
                config.shading().key(), config.recursionMax(), elapsed / 1e6);
        return Main.OK;
    }

    static int bench(Path scenePath, Config config, int frames, PrintWriter out) throws InputException {
        Scene scene = SceneLoader.load(scenePath, config.limits().scene());
        RenderScene compiled = RenderScene.compile(scene, RenderSettings.of(config));
        FrameBuffer frame = new FrameBuffer(config.displayWidth(), config.displayHeight());
        double[] millis = new double[frames];
        long raysPerFrame;
        try (Tracer tracer = new Tracer(config.effectiveThreads())) {
            for (int i = 0; i < frames; i++) {
                long cpuBefore = tracer.renderCpuNanos();
                long start = System.nanoTime();
                tracer.render(compiled, frame, config.samples(), 0, config.screenDivider());
                millis[i] = (System.nanoTime() - start) / 1e6;
                out.println(frameLine(i + 1, millis[i], tracer.renderCpuNanos(), cpuBefore));
            }
            raysPerFrame = tracer.raysCast() / frames; // every frame of the still camera casts the same rays
        }
        double[] sorted = millis.clone();
        Arrays.sort(sorted);
        double median = frames % 2 == 1 ? sorted[frames / 2] : (sorted[frames / 2 - 1] + sorted[frames / 2]) / 2;
        double p95 = sorted[(int) Math.ceil(0.95 * frames) - 1];
        // rays: camera, reflected, refracted and shadow rays of one frame, per second of the median frame
        out.printf(Locale.ROOT, "bench: frames=%d median_ms=%.2f p95_ms=%.2f rays_per_s=%.0f%n",
                frames, median, p95, raysPerFrame / (median / 1000));
        return Main.OK;
    }

    /**
     * A frame's line of {@code --bench}: its wall-clock time, then the CPU time of the render threads
     * (summed), which leaves out the time they waited for a core; without the CPU time where the JVM
     * cannot measure it.
     */
    static String frameLine(int frame, double millis, long cpuNanosAfter, long cpuNanosBefore) {
        String line = String.format(Locale.ROOT, "frame %d: %.2f ms", frame, millis);
        if (cpuNanosBefore < 0) {
            return line;
        }
        return line + String.format(Locale.ROOT, ", render cpu %.2f ms", (cpuNanosAfter - cpuNanosBefore) / 1e6);
    }
}
