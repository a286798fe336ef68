package glint.ui.capture;

import glint.config.Config;
import glint.config.JarCommand;
import glint.config.LightTransport;
import glint.image.ImageWriter;
import glint.image.PartFile;
import glint.image.PartGuard;
import glint.input.InputException;
import glint.render.FrameBuffer;
import glint.render.RenderScene;
import glint.render.Tracer;
import glint.scene.Camera;
import java.io.IOException;
import java.io.InterruptedIOException;
import java.io.PrintWriter;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;

/**
 * The window's render key: the view rendered as a still image, as {@code --output} renders it, on a thread
 * and tracer of its own, so that the window's frames go on. Cancelled by the same key or Esc, or when the
 * window closes, while it renders and while its image is encoded and written: a cancelled still is
 * cancelled at once (a tile still being traced finishes on its own, and its result is dropped), so the
 * next key press starts a new still. The image is written as headless stills are: to a hidden file beside
 * it, made before the render, renamed when complete, so that no file is ever seen half written or left
 * behind; the rename and the cancel exclude each other, so "cancelled, nothing written" is always true.
 * Engine thread only, except where a method says otherwise.
 */
public final class StillRender implements AutoCloseable {

    /** While a still renders, the engine looks at its progress this often. */
    public static final long POLL_NANOS = 250_000_000L;
    /** What the overlay says once a still is cancelled, at once. */
    static final String CANCELLED = "still: cancelled, nothing written";
    private static final String RENDERING = "still: rendering ";
    private static final String WRITING = "still: writing ";
    /** What a guard says if the program ends too abruptly to delete a still's hidden files itself. */
    private static final String ENDED = "glint: the program ended before the still was written; nothing written, "
            + "its hidden temporary files removed";

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

        /** The files written, for the overlay and the report: {@code a.png} or {@code a.png and a.pfm}. */
        String files() {
            return png + (pfm != null ? " and " + pfm : "");
        }

        List<Path> images() {
            return pfm == null ? List.of(png) : List.of(png, pfm);
        }
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
                + String.format(Locale.ROOT, "  %s --scene %s --width %d --height %d --spp %d"
                        + " --shading %s%s --depth %d --output %s%n", JarCommand.java(), JarCommand.word(scenePath.toString()),
                        still.displayWidth(), still.displayHeight(), still.samples(), still.shading().key(),
                        path ? " --integrator path" : "", still.recursionMax(), JarCommand.word(png.getFileName().toString()))
                + CameraBlock.yaml(printed);
        Path pfmFile = pfm ? png.resolveSibling(png.getFileName().toString().replaceFirst("\\.png$", ".pfm")) : null;
        return new Job(scene, still.displayWidth(), still.displayHeight(), still.samples(), still.effectiveThreads(),
                still.screenDivider(), png, pfmFile, settings, recipe);
    }

    /** Whether an overlay line says a still is under way (which Enter or Esc then cancels). Any thread. */
    public static boolean underWay(String overlayLine) {
        return overlayLine.startsWith(RENDERING) || overlayLine.startsWith(WRITING);
    }

    private final Runnable changed;
    private final List<Still> stills = new ArrayList<>(); // every still whose thread may still run
    private Still current; // the last one started

    /** @param changed wakes the engine when a still is written, fails or stops */
    public StillRender(Runnable changed) {
        this.changed = changed;
    }

    /** Whether a still is under way: started, not cancelled, not ended. */
    boolean running() {
        return current != null && current.underWay();
    }

    /** Starts a still (returns what the overlay says), or, if one is under way, cancels it. */
    String startOrCancel(Job job, PrintWriter out, PrintWriter err) {
        if (running()) {
            return cancel();
        }
        stills.removeIf(s -> s.ended.getCount() == 0);
        current = new Still(job, current, out, err);
        stills.add(current);
        current.thread.start();
        return current.progressLine();
    }

    /** Cancels the still under way (none is written); returns what the overlay says. */
    String cancel() {
        return current == null ? CANCELLED : current.cancel();
    }

    /** What changed since the last call (progress, written, failed), if anything. */
    Optional<String> news() {
        Still s = current;
        if (s == null) {
            return Optional.empty();
        }
        String n = s.news.getAndSet(null);
        return n == null && s.underWay() ? Optional.of(s.progressLine()) : Optional.ofNullable(n);
    }

    /**
     * Cancels a still under way and waits (a bounded time) until every still's thread has cleaned up;
     * returns whether a still under way was cancelled by it.
     */
    boolean stop() {
        boolean stopped = running() && cancel().equals(CANCELLED); // not when it was just renamed into place
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        for (Still s : stills) {
            s.tracer.cancel();
            try {
                s.ended.await(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                break;
            }
        }
        return stopped;
    }

    @Override
    public void close() {
        stop();
    }

    /**
     * Why {@code image} could not be written, in words, naming it, never its hidden file (which the
     * system's error names): {@code /photos/a.png: permission denied}.
     */
    static String why(IOException e, Path image) {
        String name = InputException.cutPath(image.toString());
        if (e instanceof AccessDeniedException) {
            return name + ": permission denied";
        }
        if (e instanceof NoSuchFileException) {
            return name + ": no such folder";
        }
        if (e instanceof FileSystemException f && f.getReason() != null) {
            return name + ": " + f.getReason();
        }
        return name + ": " + (e.getMessage() != null ? e.getMessage() : e.toString());
    }

    /** One still: its thread, its tracer, and how far it is. */
    private final class Still implements ImageWriter.Watcher {
        private final Job job;
        private Still previous; // may still be finishing a tile: this one waits for it (one frame in memory)
        private final PrintWriter out;
        private final PrintWriter err;
        private final Tracer tracer;
        private final Thread thread;
        private final CountDownLatch ended = new CountDownLatch(1);
        private final AtomicReference<String> news = new AtomicReference<>(); // the last thing to show
        private volatile boolean cancelled;
        // under this object's lock, as cancelled is set: the hidden files, and whether they are in place
        private final List<PartFile> parts = new ArrayList<>();
        private boolean renamed;
        private volatile int filesWritten;
        private volatile double writeFraction = -1; // of the file being written; below 0: still rendering

        Still(Job job, Still previous, PrintWriter out, PrintWriter err) {
            this.job = job;
            this.previous = previous;
            this.out = out;
            this.err = err;
            this.tracer = new Tracer(job.threads());
            this.thread = new Thread(this::run, "glint-still");
        }

        boolean underWay() {
            return !cancelled && ended.getCount() > 0;
        }

        /** Cancelled at once: no rename can follow, and the hidden files are gone before the overlay says so. */
        String cancel() {
            synchronized (this) {
                if (renamed) {
                    return "still: wrote " + job.files(); // too late: it is there
                }
                cancelled = true;
                parts.forEach(PartFile::delete); // a write under way goes on into nothing, and stops at its next bytes
            }
            tracer.cancel();
            return CANCELLED;
        }

        @Override
        public boolean cancelled() {
            return cancelled;
        }

        @Override
        public void progress(double fraction) {
            writeFraction = fraction;
        }

        String progressLine() {
            double f = writeFraction;
            if (f < 0) {
                int percent = (int) (100L * tracer.tilesDone() / Math.max(1, tracer.frameTiles()));
                return RENDERING + percent + " % (Enter or Esc cancels)";
            }
            int percent = (int) (100 * (filesWritten + Math.min(1, f)) / job.images().size());
            return WRITING + percent + " % (Enter or Esc cancels)";
        }

        private void run() {
            long start = System.nanoTime();
            PartGuard guard = null;
            try {
                awaitPrevious();
                guard = PartGuard.of(makeParts(), ENDED);
                FrameBuffer frame = new FrameBuffer(job.width(), job.height());
                checkCancelled();
                tracer.render(job.scene(), frame, job.samples(), 0, job.divider());
                write(frame);
                report(start);
            } catch (CancellationException | InterruptedIOException e) {
                // said when it was cancelled
            } catch (IOException | RuntimeException | OutOfMemoryError e) {
                String why = e instanceof OutOfMemoryError ? "out of memory" : e.getMessage() != null ? e.getMessage()
                        : e.toString();
                err.println("glint: still not written: " + why);
                news.set("still not written: " + why);
            } finally {
                synchronized (this) {
                    parts.forEach(PartFile::close); // renamed into place, or deleted wherever its folder is now
                }
                if (guard != null) {
                    guard.close();
                }
                tracer.close();
                ended.countDown();
                changed.run();
            }
        }

        /** Waits until the still before this one (cancelled) has let go of its frame, or this one is cancelled. */
        private void awaitPrevious() throws InterruptedIOException {
            try {
                while (previous != null && !previous.ended.await(50, TimeUnit.MILLISECONDS)) {
                    checkCancelled();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new InterruptedIOException("interrupted");
            }
            previous = null; // let go of it: no chain of old stills is kept
            checkCancelled();
        }

        private void checkCancelled() {
            if (cancelled) {
                throw new CancellationException();
            }
        }

        /** The hidden files, made before the work (a folder that cannot be written is found now); their paths. */
        private List<Path> makeParts() throws IOException {
            synchronized (this) {
                checkCancelled();
                for (Path image : job.images()) {
                    try {
                        parts.add(PartFile.beside(image));
                    } catch (IOException e) {
                        throw new IOException(why(e, image), e);
                    }
                }
                return parts.stream().map(PartFile::path).toList();
            }
        }

        /** Each file written to its hidden one, then all renamed into place, unless cancelled before. */
        private void write(FrameBuffer frame) throws IOException {
            writeFraction = 0;
            List<Path> images = job.images();
            for (int i = 0; i < images.size(); i++) {
                filesWritten = i;
                writeFraction = 0;
                try {
                    ImageWriter.writeTemporary(frame, images.get(i), parts.get(i).path(), this);
                } catch (InterruptedIOException e) {
                    throw e;
                } catch (IOException e) {
                    throw new IOException(why(e, images.get(i)), e);
                }
            }
            synchronized (this) {
                if (cancelled) {
                    throw new InterruptedIOException("cancelled");
                }
                for (int i = 0; i < images.size(); i++) {
                    try {
                        ImageWriter.rename(parts.get(i).path(), images.get(i));
                    } catch (IOException e) {
                        if (i == 0) {
                            throw new IOException(why(e, images.get(0)), e);
                        }
                        renamed = true; // the PNG is there: say so, and why the PFM is not
                        throw new IOException(why(e, images.get(i)) + " (" + images.get(0) + " was written)", e);
                    }
                }
                renamed = true;
            }
        }

        /** Standard output gets the files, then the command and camera that make them headless. */
        private void report(long start) {
            String files = job.files();
            String failed = Printing.print(out, String.format(Locale.ROOT, "still: wrote %s (%s) in %.1f s%n%s", files,
                    job.settings(), (System.nanoTime() - start) / 1e9, job.recipe()));
            if (failed != null) {
                err.println("glint: still: wrote " + files + "; its report not printed: " + failed);
            }
            news.set("still: wrote " + files + (failed == null ? "" : "; its report not printed: " + failed));
        }
    }
}
