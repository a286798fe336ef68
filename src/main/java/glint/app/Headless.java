package glint.app;

import glint.config.Config;
import glint.config.Flags;
import glint.image.FrameBuffer;
import glint.input.InputException;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Tracer;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import glint.still.MemoryCheck;
import glint.still.StillRefused;
import glint.still.StillRun;
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
    /** What a still stopped by a signal before its image was written says. */
    static final String INTERRUPTED_STILL = "glint: interrupted; no image written";

    private Headless() {
    }

    /**
     * Renders one still to {@code output}, at the settings the flags, the scene's render block and
     * the config give, in that order, through the one still pipeline ({@link StillRun}). The output is
     * checked first, before the scene is read, against everything that would otherwise fail only at the
     * end or lose a file ({@link glint.still.OutputFile}); its size, with the heap, before the render.
     *
     * @param inputs the scene file, then the config file if one was read: the output may be neither
     */
    static int renderStill(Path scenePath, ViewChoice view, List<Path> inputs, Config settings, Flags flags,
                           Path output, PrintWriter out, PrintWriter err) throws InputException, IOException {
        try (Interrupts interrupts = Interrupts.install(err, INTERRUPTED_STILL);
             Progress progress = Progress.start(err);
             StillRun still = StillRun.open(List.of(output), inputs, "image")) {
            interrupts.clearLineWith(progress::close); // its line never lands on the bar's
            interrupts.watch(still::cancel);
            try {
                return render(still, scenePath, view, settings, flags, progress, out);
            } catch (CancellationException | InterruptedIOException e) {
                interrupts.report(INTERRUPTED_STILL);
                return INTERRUPTED;
            }
        } catch (StillRefused e) {
            throw refusal(e);
        }
    }

    private static int render(StillRun still, Path scenePath, ViewChoice view, Config settings, Flags flags,
                              Progress progress, PrintWriter out) throws InputException, IOException, StillRefused {
        progress.step("reading the scene", null);
        Scene scene = view.apply(SceneLoader.load(scenePath, settings.limits().scene()), scenePath.toString());
        Config config = flags.effective(settings, scene.render(), progress::note);
        progress.step("preparing the scene", null);
        RenderScene compiled = RenderScene.compile(scene, config.renderSettings());
        long start = System.nanoTime();
        still.write(still.render(compiled, config, progress::step), progress::step);
        long elapsed = System.nanoTime() - start;
        progress.close(); // a bar on the terminal is cleared first
        Path output = still.images().get(0);
        try {
            out.printf(Locale.ROOT, "wrote %s (%s) in %.1f ms%n", InputException.printable(output.toString()),
                    StillRun.describe(config, true), elapsed / 1e6);
            String spent = still.samplesSpent();
            if (!spent.isEmpty()) {
                out.println("samples spent: " + spent);
            }
            out.flush();
        } catch (Output.Failure e) { // the image is there all the same
            throw e.after(InputException.cutPath(output.toString()) + " was written");
        }
        return Main.OK;
    }

    /** A refusal before the work, as the bad input it is: {@code glint: --output: ...}, status 2. */
    static InputException refusal(StillRefused e) {
        return new InputException("glint", 0, 0, (e.aboutOutput() ? "--output: " : "") + e.problem());
    }

    static int bench(Path scenePath, ViewChoice view, Config settings, Flags flags, int frames, PrintWriter out,
                     PrintWriter err) throws InputException {
        try (Interrupts interrupts = Interrupts.install(err, INTERRUPTED_BENCH);
             Progress progress = Progress.start(err)) {
            interrupts.clearLineWith(progress::close);
            progress.step("reading the scene", null);
            Scene loaded = SceneLoader.load(scenePath, settings.limits().scene());
            Scene scene = view.apply(loaded, scenePath.toString());
            Config config = flags.effective(settings, scene.render(), progress::note);
            progress.step("preparing the scene", null);
            RenderScene compiled = RenderScene.compile(scene, config.renderSettings());
            try {
                MemoryCheck.check(config, MemoryCheck.FRAME_BYTES_PER_PIXEL, Runtime.getRuntime());
            } catch (StillRefused e) {
                throw refusal(e);
            }
            progress.close(); // the frames' lines are the progress from here
            return timeFrames(compiled, config, view.isView() ? ", " + view.describe(loaded) : "", scenePath, frames,
                    interrupts, out);
        }
    }

    /** What --bench says when a signal stops it before its first frame (while its scene loads). */
    static final String INTERRUPTED_BENCH = "glint: interrupted before the first frame";

    private static int timeFrames(RenderScene compiled, Config config, String seen, Path scenePath, int frames,
                                  Interrupts interrupts, PrintWriter out) {
        FrameBuffer frame = new FrameBuffer(config.displayWidth(), config.displayHeight());
        double[] millis = new double[frames];
        long raysPerFrame;
        out.printf(Locale.ROOT, "timing %d %s of %s%s (%s)%n", frames, frames == 1 ? "frame" : "frames",
                InputException.printable(InputException.cutPath(scenePath.toString())), seen, StillRun.describe(config, true));
        try (Tracer tracer = new Tracer(config.effectiveThreads())) {
            interrupts.watch(() -> {
                tracer.cancel();
                return true;
            });
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
