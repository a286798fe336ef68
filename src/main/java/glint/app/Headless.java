package glint.app;

import glint.config.Config;
import glint.config.LightTransport;
import glint.config.Flags;
import glint.image.ImageWriter;
import glint.image.PartFile;
import glint.image.PartGuard;
import glint.input.InputException;
import glint.render.FrameBuffer;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Tracer;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import java.io.IOException;
import java.io.InterruptedIOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CancellationException;

/** The modes without a window: render one still to a file, or time frames (--bench). */
final class Headless {

    /**
     * Exit status of a run stopped by Ctrl-C (128 + SIGINT), as shells report it; the JVM itself
     * exits with 128 + the number of the signal that stopped it (143 for SIGTERM).
     */
    static final int INTERRUPTED = 130;
    /** The most frames --bench renders. */
    static final int MAX_BENCH_FRAMES = 100_000;
    /**
     * Heap bytes a render thread needs per camera ray of a tile's row (its row buffers: a direction
     * and a radiance, 7 doubles, with room to spare), and per pixel of a still: the float frame (12)
     * and the 8-bit image written from it (4).
     */
    static final long ROW_BYTES_PER_RAY = 64;
    static final long STILL_BYTES_PER_PIXEL = 16;
    /** Heap kept free for everything else: the scene, the JVM's own needs. */
    static final long HEAP_RESERVE = 32L << 20;

    private Headless() {
    }

    /**
     * Renders one still to {@code output}, at the settings the flags, the scene's render block and
     * the config give, in that order. The output is checked first (its size once the scene is read),
     * before any work, against everything that would otherwise fail only at the end or lose a file
     * ({@link OutputFile}).
     *
     * @param inputs the scene file, then the config file if one was read: the output may be neither
     */
    static int renderStill(Path scenePath, ViewChoice view, List<Path> inputs, Config settings, Flags flags,
                           Path output, PrintWriter out, PrintWriter err) throws InputException, IOException {
        PartFile temp = null;
        PartGuard guard = null;
        try (Interrupts interrupts = Interrupts.install(err, "glint: interrupted; no image written");
             Progress progress = Progress.start(err)) {
            temp = OutputFile.prepare(output, inputs);
            guard = PartGuard.of(List.of(temp.path()), ENDED); // SIGKILL, a crash: no hook runs
            interrupts.watch(null, temp);
            progress.step("reading the scene", null);
            Scene scene = view.apply(SceneLoader.load(scenePath, settings.limits().scene()), scenePath.toString());
            Config config = flags.effective(settings, scene.render());
            OutputFile.checkSize(output, config.displayWidth(), config.displayHeight());
            progress.step("preparing the scene", null);
            RenderScene compiled = RenderScene.compile(scene, RenderSettings.of(config));
            checkMemory(config, STILL_BYTES_PER_PIXEL, Runtime.getRuntime());
            FrameBuffer frame = new FrameBuffer(config.displayWidth(), config.displayHeight());
            long start = System.nanoTime();
            try (Tracer tracer = new Tracer(config.effectiveThreads())) {
                interrupts.watch(tracer, temp);
                progress.step("rendering", () -> tracer.tilesDone() / (double) tracer.frameTiles());
                tracer.render(compiled, frame, config.samples(), 0, config.screenDivider());
            } catch (CancellationException e) {
                interrupts.report("glint: interrupted; no image written");
                return INTERRUPTED;
            }
            progress.step("writing the image", interrupts::writeProgress);
            OutputFile.keepPermissions(output, temp.path());
            try {
                ImageWriter.write(frame, output, temp.path(), interrupts);
            } catch (InterruptedIOException e) {
                interrupts.report("glint: interrupted; no image written");
                return INTERRUPTED;
            } catch (IOException e) {
                throw new WriteFailure(output, e);
            }
            long elapsed = System.nanoTime() - start;
            progress.close(); // a bar on the terminal is cleared first
            try {
                out.printf(Locale.ROOT, "wrote %s (%s) in %.1f ms%n", InputException.printable(output.toString()),
                        settingsOf(config), elapsed / 1e6);
                out.flush();
            } catch (Output.Failure e) { // the image is there all the same
                throw e.after(InputException.cutPath(output.toString()) + " was written");
            }
            return Main.OK;
        } finally {
            if (temp != null) {
                temp.close(); // wherever its folder is now: renamed during the render, it keeps nothing
            }
            if (guard != null) {
                guard.close();
            }
        }
    }

    /** What a guard says if the program ends too abruptly (SIGKILL) to delete the hidden file itself. */
    static final String ENDED = "glint: the program ended before the image was written; nothing written, "
            + "its hidden temporary file removed";

    /** Why an image could not be written, in one line: {@code cannot write out.png: No space left on device}. */
    static final class WriteFailure extends IOException {
        WriteFailure(Path output, IOException cause) {
            super("cannot write " + InputException.cutPath(output.toString()) + ": " + OutputFile.reason(cause), cause);
        }
    }

    /**
     * Refuses, before any memory is taken, a render the Java heap cannot hold: the frame (and image)
     * and every render thread's row buffers, which grow with the tile width times the samples.
     */
    static void checkMemory(Config config, long bytesPerPixel, Runtime runtime) throws InputException {
        checkMemory(config, bytesPerPixel, runtime.maxMemory() - (runtime.totalMemory() - runtime.freeMemory()));
    }

    /** The same check against {@code freeHeap} bytes. */
    static void checkMemory(Config config, long bytesPerPixel, long freeHeap) throws InputException {
        long need = memoryNeeded(config, bytesPerPixel);
        long available = freeHeap - HEAP_RESERVE;
        if (need > available) {
            String needed = megabytes(need), free = megabytes(Math.max(0, available));
            if (needed.equals(free)) { // the difference is less than a megabyte
                needed = String.format(Locale.ROOT, "%,d bytes", need);
                free = String.format(Locale.ROOT, "%,d bytes", Math.max(0, available));
            }
            throw new InputException("glint", 0, 0, String.format(Locale.ROOT,
                    "%dx%d at %d %s with %d %s needs about %s of memory; the Java heap has %s free "
                    + "(render fewer pixels, samples or threads, or start Java with a larger -Xmx)",
                    config.displayWidth(), config.displayHeight(), config.samples(),
                    config.samples() == 1 ? "sample" : "samples", config.effectiveThreads(),
                    config.effectiveThreads() == 1 ? "thread" : "threads", needed, free));
        }
    }

    /** Heap bytes a headless render of this config needs, computed in long (no overflow). */
    static long memoryNeeded(Config config, long bytesPerPixel) {
        long w = config.displayWidth(), h = config.displayHeight();
        long divider = Math.max(1, Math.min(config.screenDivider(), Math.min(w, h)));
        long tileWidth = (w + divider - 1) / divider;
        long rowRays = tileWidth * config.samples();
        return w * h * bytesPerPixel + config.effectiveThreads() * rowRays * ROW_BYTES_PER_RAY;
    }

    private static String megabytes(long bytes) {
        return String.format(Locale.ROOT, "%,d MB", (bytes + (1 << 20) - 1) >> 20);
    }

    /**
     * What a run renders with, as its report line says it: {@code 800x600, 4 spp, 2 threads, cook-torrance, depth 16}
     * ({@code cook-torrance, path, depth 16} with the path integrator).
     */
    static String settingsOf(Config config) {
        return String.format(Locale.ROOT, "%dx%d, %d spp, %d threads, %s%s, depth %d", config.displayWidth(),
                config.displayHeight(), config.samples(), config.effectiveThreads(), config.shading().key(),
                config.transport() == LightTransport.PATH ? ", path" : "", config.recursionMax());
    }

    static int bench(Path scenePath, ViewChoice view, Config settings, Flags flags, int frames, PrintWriter out,
                     PrintWriter err) throws InputException {
        Scene loaded = SceneLoader.load(scenePath, settings.limits().scene());
        Scene scene = view.apply(loaded, scenePath.toString());
        Config config = flags.effective(settings, scene.render());
        RenderScene compiled = RenderScene.compile(scene, RenderSettings.of(config));
        checkMemory(config, 12, Runtime.getRuntime());
        FrameBuffer frame = new FrameBuffer(config.displayWidth(), config.displayHeight());
        double[] millis = new double[frames];
        long raysPerFrame;
        String seen = view.isView() ? ", " + view.describe(loaded) : "";
        out.printf(Locale.ROOT, "timing %d %s of %s%s (%s)%n", frames, frames == 1 ? "frame" : "frames",
                InputException.printable(InputException.cutPath(scenePath.toString())), seen, settingsOf(config));
        try (Interrupts interrupts = Interrupts.install(err, "glint: interrupted");
             Tracer tracer = new Tracer(config.effectiveThreads())) {
            interrupts.watch(tracer, null);
            for (int i = 0; i < frames; i++) {
                long cpuBefore = tracer.renderCpuNanos();
                long start = System.nanoTime();
                try {
                    tracer.render(compiled, frame, config.samples(), 0, config.screenDivider());
                } catch (CancellationException e) {
                    interrupts.report("glint: interrupted after " + i + (i == 1 ? " frame" : " frames"));
                    return INTERRUPTED;
                }
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
