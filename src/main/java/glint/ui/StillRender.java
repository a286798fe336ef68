package glint.ui;

import glint.config.Config;
import glint.config.LightTransport;
import glint.image.ImageWriter;
import glint.render.FrameBuffer;
import glint.render.RenderScene;
import glint.render.Tracer;
import glint.scene.Camera;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.CancellationException;
import java.util.concurrent.TimeUnit;

/**
 * The window's render key: the view rendered as a still image, as {@code --output} renders it, on a thread
 * and tracer of its own, so that the window's frames go on. One at a time; cancelled by the same key or
 * Esc, or when the window closes. The image is written as headless stills are: to a hidden file beside it,
 * renamed when complete, so that no file is ever seen half written or left behind.
 */
final class StillRender implements AutoCloseable {

    /** While a still renders, the engine looks at its progress this often. */
    static final long POLL_NANOS = 250_000_000L;

    /**
     * What to render and where.
     *
     * @param scene    the compiled scene with the camera as printed
     * @param width    image size
     * @param height   image size
     * @param samples  samples per pixel
     * @param threads  render threads
     * @param divider  tiles per side
     * @param png      the PNG to write
     * @param pfm      the PFM to write beside it, or null
     * @param settings how it was made, for the report ("800x600, 16 spp, phong, depth 16")
     * @param recipe   the camera block and command that make the same image headless, printed after it
     */
    record Job(RenderScene scene, int width, int height, int samples, int threads, int divider, Path png, Path pfm,
               String settings, String recipe) {
    }

    /**
     * The job for a view: {@code still} holds the still's settings (size, samples, shading, depth, threads),
     * {@code scene} is compiled with them and seen from {@code printed}, the camera as key C prints it.
     */
    static Job job(RenderScene scene, Camera printed, Config still, Path scenePath, Screenshots folder, boolean pfm) {
        // named after the scene: phong-classic-20261202-153000-123.png, in the screenshots' folder
        Path png = folder.name(scenePath.getFileName().toString().replaceFirst("\\.[^.]*$", ""), ".png");
        boolean path = still.transport() == LightTransport.PATH;
        String settings = String.format(Locale.ROOT, "%dx%d, %d spp, %s%s, depth %d", still.displayWidth(),
                still.displayHeight(), still.samples(), still.shading().key(), path ? ", path" : "",
                still.recursionMax());
        String recipe = "still: the same image headless, with this camera in " + scenePath + ":\n"
                + String.format(Locale.ROOT, "  java -jar target/glint.jar --scene %s --width %d --height %d --spp %d"
                        + " --shading %s%s --depth %d --output %s%n", scenePath, still.displayWidth(),
                        still.displayHeight(), still.samples(), still.shading().key(),
                        path ? " --integrator path" : "", still.recursionMax(), png.getFileName())
                + CameraBlock.yaml(printed);
        Path pfmFile = pfm ? png.resolveSibling(png.getFileName().toString().replaceFirst("\\.png$", ".pfm")) : null;
        return new Job(scene, still.displayWidth(), still.displayHeight(), still.samples(), still.effectiveThreads(),
                still.screenDivider(), png, pfmFile, settings, recipe);
    }

    private final Runnable changed;
    private volatile Tracer tracer;
    private volatile Thread thread;
    private volatile String news; // the last thing to show, until the engine takes it
    private volatile boolean cancelled;

    /** @param changed wakes the engine when a still is written, fails or stops */
    StillRender(Runnable changed) {
        this.changed = changed;
    }

    /** Whether a still is being rendered. */
    boolean running() {
        Thread t = thread;
        return t != null && t.isAlive();
    }

    /** Starts a still (returns what the overlay says), or, if one is under way, cancels it. */
    String startOrCancel(Job job, PrintWriter out, PrintWriter err) {
        if (running()) {
            return cancel();
        }
        cancelled = false;
        Tracer t = new Tracer(job.threads());
        tracer = t;
        Thread worker = new Thread(() -> render(job, t, out, err), "glint-still");
        thread = worker;
        worker.start();
        return progressLine();
    }

    /** Cancels the still under way; no file is written. */
    String cancel() {
        cancelled = true;
        Tracer t = tracer;
        if (t != null) {
            t.cancel();
        }
        return "still: cancelling";
    }

    /** What changed since the last call (progress, written, cancelled, failed), if anything. */
    Optional<String> news() {
        String n = news;
        news = null;
        if (n == null && running()) {
            return Optional.of(progressLine());
        }
        return Optional.ofNullable(n);
    }

    private String progressLine() {
        Tracer t = tracer;
        int percent = t == null ? 0 : (int) (100L * t.tilesDone() / Math.max(1, t.frameTiles()));
        return "still: rendering " + percent + " % (Enter or Esc cancels)";
    }

    private void render(Job job, Tracer t, PrintWriter out, PrintWriter err) {
        long start = System.nanoTime();
        try (t) {
            FrameBuffer frame = new FrameBuffer(job.width(), job.height());
            t.render(job.scene(), frame, job.samples(), 0, job.divider());
            if (cancelled) {
                throw new CancellationException();
            }
            write(frame, job.png());
            if (job.pfm() != null) {
                write(frame, job.pfm());
            }
            String files = job.png() + (job.pfm() != null ? " and " + job.pfm() : "");
            out.printf(Locale.ROOT, "still: wrote %s (%s) in %.1f s%n%s", files, job.settings(),
                    (System.nanoTime() - start) / 1e9, job.recipe());
            out.flush();
            news = "still: wrote " + files;
        } catch (CancellationException e) {
            news = "still: cancelled, nothing written";
        } catch (IOException | RuntimeException | OutOfMemoryError e) {
            String why = e instanceof OutOfMemoryError ? "out of memory" : e.getMessage() != null ? e.getMessage()
                    : e.toString();
            err.println("glint: still not written: " + why);
            news = "still not written: " + why;
        } finally {
            tracer = null;
            changed.run();
        }
    }

    /** Written aside and renamed when complete, as headless stills are; the aside file never stays. */
    private void write(FrameBuffer frame, Path file) throws IOException {
        Path temp = ImageWriter.temporaryBeside(file);
        try {
            if (cancelled) {
                throw new CancellationException();
            }
            ImageWriter.write(frame, file, temp);
        } finally {
            Files.deleteIfExists(temp);
        }
    }

    /** Cancels a still under way and waits (a bounded time) until its thread has cleaned up. */
    @Override
    public void close() {
        Thread t = thread;
        if (t == null) {
            return;
        }
        cancel();
        try {
            t.join(TimeUnit.SECONDS.toMillis(30));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
