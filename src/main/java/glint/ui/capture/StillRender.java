package glint.ui.capture;

import glint.config.Config;
import glint.config.JarCommand;
import glint.image.ViewTransform;
import glint.input.InputException;
import glint.render.RenderScene;
import glint.scene.Camera;
import glint.still.StillRefused;
import glint.still.StillRun;
import java.io.IOException;
import java.io.InterruptedIOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.zip.CRC32;

/**
 * The window's render key: the view rendered as a still image through the pipeline {@code --output} uses
 * ({@link StillRun}: the same checks, hidden files, write and rename), on a thread of its own, so that the
 * window's frames go on. Cancelled by the same key or Esc, or when the window closes, while it renders and
 * while its image is encoded and written: a cancelled still is cancelled at once (a tile still being traced
 * finishes on its own, and its result is dropped), so the next key press starts a new still. Engine thread
 * only, except where a method says otherwise.
 */
public final class StillRender implements AutoCloseable {

    /** While a still renders, the engine looks at its progress this often. */
    public static final long POLL_NANOS = 250_000_000L;
    /** What the overlay says once a still is cancelled, at once. */
    static final String CANCELLED = "still: cancelled, nothing written";
    private static final String RENDERING = "still: rendering ";
    private static final String WRITING = "still: writing ";

    /**
     * What to render and where.
     *
     * @param scene    the compiled scene with the camera as printed
     * @param config   the still's size, samples, threads and tiles
     * @param png      the PNG to write
     * @param pfm      the PFM to write beside it, or null
     * @param settings how it was made, for the report ("800x600, 16 spp, phong, depth 16")
     * @param recipe   the camera block and command that make the same image headless, printed after it
     */
    record Job(RenderScene scene, Config config, Path png, Path pfm, String settings, String recipe) {

        /** The files written, for the overlay and the report: {@code a.png} or {@code a.png and a.pfm}. */
        String files() {
            return InputException.printable(png + (pfm != null ? " and " + pfm : ""));
        }

        List<Path> images() {
            return pfm == null ? List.of(png) : List.of(png, pfm);
        }
    }

    /**
     * The job for a view: {@code still} holds the still's settings (size, samples, shading, depth, threads),
     * {@code scene} is compiled with them and seen from {@code printed}, the camera as key C prints it.
     */
    static Job job(RenderScene scene, Camera printed, Config still, Path scenePath, Path configFile,
                   Screenshots folder, boolean pfm) {
        // named after the scene: phong-classic-20261202-153000-123.png, in the screenshots' folder
        Path png = folder.name(stem(scenePath), ".png");
        String config = configFile == null ? "" : " --config " + JarCommand.word(configFile.toString());
        String recipe = "still: the same image headless, with this camera in "
                + InputException.printable(scenePath.toString()) + ":\n"
                + String.format(Locale.ROOT, "  %s%s --scene %s --width %d --height %d --spp %d"
                        + " --shading %s --integrator %s --depth %d --exposure %s --tone %s%s --output %s%n",
                        JarCommand.java(), config, JarCommand.word(scenePath.toString()), still.displayWidth(),
                        still.displayHeight(), still.samples(), still.shading().key(), still.transport().key(),
                        still.recursionMax(), ViewTransform.stops(still.view().exposure()), still.view().tone().key(),
                        adaptive(still), JarCommand.word(png.getFileName().toString()))
                + CameraBlock.yaml(printed);
        Path pfmFile = pfm ? png.resolveSibling(png.getFileName().toString().replaceFirst("\\.png$", ".pfm")) : null;
        return new Job(scene, still, png, pfmFile, StillRun.describe(still, false), recipe);
    }

    /**
     * The headless command's adaptive sampling, where the still is rendered by it (a window started with
     * {@code --noise}, say): {@code  --noise 0.02 --max-samples 1024}; empty for a still of {@code --spp} a pixel.
     */
    private static String adaptive(Config still) {
        return still.adaptiveStill() ? " --noise " + new java.math.BigDecimal(Double.toString(still.noise()))
                .stripTrailingZeros().toPlainString() + " --max-samples " + still.maxSamples() : "";
    }

    /** The most bytes (UTF-8) of a scene's name a still's name begins with; a file's name may have 255. */
    static final int STEM_BYTES = 100;

    /**
     * What a still's name begins with: the scene file's name without its extension, or, when that is longer
     * than {@link #STEM_BYTES}, its first characters and a code of the whole ({@code aaaa-1a2b3c4d}), so that
     * the still's name fits the file system and two scenes whose long names differ only at the end still name
     * their stills apart. Control characters (a line break, a terminal's escape) become {@code _}.
     */
    static String stem(Path scenePath) {
        String name = scenePath.getFileName().toString().replaceFirst("\\.[^.]*$", "");
        StringBuilder plain = new StringBuilder(); // a line break or a terminal's escape in a name: _
        name.codePoints().mapToObj(Character::toString)
                .forEach(c -> plain.append(InputException.printable(c).equals(c) ? c : "_"));
        name = plain.toString();
        byte[] utf8 = name.getBytes(StandardCharsets.UTF_8);
        if (utf8.length <= STEM_BYTES) {
            return name;
        }
        CRC32 code = new CRC32();
        code.update(utf8);
        String suffix = String.format(Locale.ROOT, "-%08x", code.getValue());
        StringBuilder start = new StringBuilder();
        int bytes = suffix.length();
        for (int c : name.codePoints().toArray()) {
            bytes += new String(Character.toChars(c)).getBytes(StandardCharsets.UTF_8).length;
            if (bytes > STEM_BYTES) {
                break;
            }
            start.appendCodePoint(c);
        }
        return start + suffix;
    }

    /** Whether an overlay line says a still is under way (which Enter or Esc then cancels). Any thread. */
    public static boolean underWay(String overlayLine) {
        return overlayLine.startsWith(RENDERING) || overlayLine.startsWith(WRITING);
    }

    private final Runnable changed;
    // every still whose thread may still run, and the last one started: read by any thread (cancelNow)
    private final List<Still> stills = new java.util.concurrent.CopyOnWriteArrayList<>();
    private volatile Still current;

    /** @param changed wakes the engine when a still is written, fails or stops */
    public StillRender(Runnable changed) {
        this.changed = changed;
    }

    /** Whether a still is under way: started, not cancelled, not ended. */
    boolean running() {
        return current != null && current.underWay();
    }

    /** Starts a still, after the one before has let go of its frame; returns what the overlay says. */
    String start(Job job, PrintWriter out, PrintWriter err) {
        stills.removeIf(s -> s.ended.getCount() == 0);
        current = new Still(job, current, out, err);
        stills.add(current);
        current.thread.start();
        return current.progressLine();
    }

    /** Cancels the still under way (none is written); returns what the overlay says. */
    String cancel() {
        return current == null || current.cancel() ? CANCELLED : "still: wrote " + current.job.files(); // too late
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
        boolean stopped = running() && current.cancel(); // not when it was just renamed into place
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        for (Still s : stills) {
            s.cancel();
            try {
                s.ended.await(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                break;
            }
        }
        return stopped;
    }

    /**
     * Cancels every still at once, without waiting for their threads (any thread: the window ends while the
     * engine's thread is held in a frame that never ends); returns whether a still under way was cancelled.
     * Their hidden files are deleted now.
     */
    boolean cancelNow() {
        Still s = current;
        boolean cancelled = s != null && s.underWay() && s.cancel();
        stills.forEach(Still::cancel);
        return cancelled;
    }

    @Override
    public void close() {
        stop();
    }

    /**
     * One still: its thread, its run through the pipeline (opened on that thread), and how far it is. Its
     * cancel goes through it, before the run is opened as after.
     */
    private final class Still {
        private final Job job;
        private Still previous; // may still be finishing a tile: this one waits for it (one frame in memory)
        private final PrintWriter out;
        private final PrintWriter err;
        private final Thread thread;
        private final CountDownLatch ended = new CountDownLatch(1);
        private final AtomicReference<String> news = new AtomicReference<>(); // the last thing to show
        // set under this object's lock: the run once opened, and whether the still was cancelled (before or since)
        private volatile StillRun run;
        private volatile boolean cancelled;
        // its end said (written or failed), while its thread still cleans up: no more progress lines after it
        private volatile boolean over;

        Still(Job job, Still previous, PrintWriter out, PrintWriter err) {
            this.job = job;
            this.previous = previous;
            this.out = out;
            this.err = err;
            this.thread = new Thread(this::run, "glint-still");
        }

        boolean underWay() {
            return !cancelled && !over && ended.getCount() > 0;
        }

        /**
         * Cancels it at once (any thread): no rename can follow, and the hidden files are gone before the
         * overlay says so. Returns false, changing nothing, when it comes too late: the images are in place.
         */
        synchronized boolean cancel() {
            if (run != null && !run.cancel()) {
                return false;
            }
            cancelled = true;
            return true;
        }

        /** The run, opened unless the still was cancelled before: its files are made under this lock. */
        private synchronized StillRun open() throws StillRefused {
            checkCancelled();
            run = StillRun.open(job.images(), List.of(), "still");
            return run;
        }

        String progressLine() {
            StillRun opened = run;
            if (opened == null) {
                return RENDERING + "0 % (Enter or Esc cancels)";
            }
            String step = opened.writing() ? WRITING + opened.percentWritten() : RENDERING + opened.percentRendered();
            return step + " % (Enter or Esc cancels)";
        }

        private void run() {
            long start = System.nanoTime();
            StillRun opened = null;
            try {
                awaitPrevious();
                opened = open();
                opened.write(opened.render(job.scene(), job.config(), StillRun.Steps.NONE), StillRun.Steps.NONE);
                report(start);
            } catch (CancellationException | InterruptedIOException e) {
                // said when it was cancelled
            } catch (StillRefused e) {
                failed(e.problem());
            } catch (IOException | RuntimeException | OutOfMemoryError e) {
                failed(e instanceof OutOfMemoryError ? "out of memory" : e.getMessage() != null ? e.getMessage()
                        : e.toString());
            } finally {
                if (opened != null) {
                    opened.close(); // renamed into place, or deleted wherever its folder is now
                }
                ended.countDown();
                changed.run();
            }
        }

        private void failed(String why) {
            err.println("glint: still not written: " + why);
            news.set("still not written: " + why);
            over = true;
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

        /** Standard output gets the files, then the command and camera that make them headless. */
        private void report(long start) {
            String files = job.files();
            String failed = Printing.print(out, String.format(Locale.ROOT, "still: wrote %s (%s) in %.1f s%n%s", files,
                    job.settings(), (System.nanoTime() - start) / 1e9, job.recipe()));
            if (failed != null) {
                err.println("glint: still: wrote " + files + "; its report not printed: " + failed);
            }
            news.set("still: wrote " + files + (failed == null ? "" : "; its report not printed: " + failed));
            over = true;
        }
    }
}
