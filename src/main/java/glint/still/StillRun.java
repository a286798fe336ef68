package glint.still;

import glint.config.Config;
import glint.image.FrameBuffer;
import glint.image.ImageWriter;
import glint.image.PartFile;
import glint.image.PartGuard;
import glint.image.ViewTransform;
import glint.render.Convergence;
import glint.render.LightTransport;
import glint.render.RenderScene;
import glint.render.Tracer;
import java.io.IOException;
import java.io.InterruptedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CancellationException;
import java.util.function.DoubleSupplier;

/**
 * One still image, from its files checked to its files in place: the one pipeline of {@code --output} and
 * the window's render key. A still comes to be opened: {@link #open} checks each image file and makes its
 * hidden file beside it ({@code .a.png.1a2b.part}) before any work, with a guard process that deletes them
 * if the program ends too abruptly to do it itself ({@link PartGuard}). Then, on one thread: {@link #render}
 * checks the size against {@code ulimit -f} and the heap, then renders on a tracer of its own; {@link #write}
 * writes each image to its hidden file and renames them all into place; {@link #close} deletes what was not
 * renamed. {@link #cancel}, from any thread at any time, stops the render or the write at once and deletes
 * the hidden files; it and the rename exclude each other, so "cancelled, nothing written" and "written" are
 * never both true. A refusal before the work is a {@link StillRefused}, a failed write a {@link WriteFailure},
 * and a cancelled still throws {@link CancellationException} (render) or {@link InterruptedIOException}
 * (write).
 */
public final class StillRun implements ImageWriter.Watcher, AutoCloseable {

    /** Where a still says which step it is on and how far that step is (the command line's progress). */
    @FunctionalInterface
    public interface Steps {
        /** Nobody is told. */
        Steps NONE = (name, done) -> { };

        /**
         * The still goes on to the next step.
         *
         * @param done the fraction of the step done, from 0 to 1
         */
        void step(String name, DoubleSupplier done);
    }

    private final List<Path> images;
    // under this object's lock, as cancelled is set: the hidden files, and whether they are in place
    private final List<PartFile> parts;
    private boolean renamed;
    private volatile boolean cancelled;
    private volatile Tracer tracer;
    private final PartGuard guard;
    // files written, with the fraction of the one being written (one value: never ahead); below 0: not yet
    private volatile double filesWritten = -1;
    private int fileWriting; // the writing thread's: the index of the file being written
    private volatile ViewTransform view = ViewTransform.STANDARD; // the PNG's: the config's that rendered the frame
    /** An adaptive still's refinement, once rendered (for its report); null for a still of {@code samples} a pixel. */
    private volatile Convergence refined;

    private StillRun(List<Path> images, List<PartFile> parts, PartGuard guard) {
        this.images = images;
        this.parts = parts;
        this.guard = guard;
    }

    /**
     * A still of {@code images} (a PNG, a PFM, or both: one frame, each in its format), opened: each image
     * file checked against what it must never be ({@code inputs}: the scene, then the config) and what would
     * fail only at the end ({@link OutputFile}), and its hidden file made. If the program ends too abruptly to
     * delete them itself, the guard process deletes them and says {@code glint: the program ended before the
     * image was written; nothing written, its hidden temporary file removed}, {@code what} naming the image.
     *
     * @param what what the user calls the image: {@code image} (the command line) or {@code still} (the window)
     */
    public static StillRun open(List<Path> images, List<Path> inputs, String what) throws StillRefused {
        List<PartFile> parts = new ArrayList<>();
        try {
            for (Path image : images) {
                parts.add(OutputFile.prepare(image, inputs));
            }
        } catch (StillRefused | RuntimeException e) {
            parts.forEach(PartFile::close);
            throw e;
        }
        List<Path> made = parts.stream().map(PartFile::path).toList();
        // SIGKILL, a crash, the X server gone: no Java code runs
        PartGuard guard = PartGuard.of(made, ended(what, images.size()));
        return new StillRun(List.copyOf(images), parts, guard);
    }

    /** What the guard process says if it has to delete the hidden files of {@code files} images. */
    private static String ended(String what, int files) {
        return "glint: the program ended before the " + what + " was written; nothing written, its hidden temporary "
                + (files == 1 ? "file" : "files") + " removed";
    }

    /** The files this still writes. */
    public List<Path> images() {
        return images;
    }

    /** Refuses a PFM of the config's size that would be larger than this process may write (ulimit -f). */
    private void checkSize(Config config) throws StillRefused {
        for (Path image : images) {
            OutputFile.checkSize(image, config.displayWidth(), config.displayHeight());
        }
    }

    /**
     * Renders {@code scene} at the config's size, samples, threads and tiles, once the size and the heap
     * allow it, into a new frame.
     */
    public FrameBuffer render(RenderScene scene, Config config, Steps steps) throws StillRefused {
        checkSize(config);
        view = config.view();
        MemoryCheck.check(config, MemoryCheck.STILL_BYTES_PER_PIXEL
                + (config.adaptiveStill() ? Convergence.BYTES_PER_PIXEL : 0), Runtime.getRuntime());
        FrameBuffer frame = new FrameBuffer(config.displayWidth(), config.displayHeight());
        Tracer t;
        synchronized (this) {
            checkCancelled();
            t = new Tracer(config.effectiveThreads());
            tracer = t;
        }
        try {
            if (config.adaptiveStill()) {
                Convergence c = new Convergence(frame.width(), frame.height(), config.noise(), config.maxSamples());
                int pixels = frame.width() * frame.height();
                // done: the larger of the passes towards the cap and the pixels that have stopped
                steps.step("rendering", () -> Math.max(c.passes() / (double) c.cap(),
                        1 - c.activePixels() / (double) pixels));
                c.refine(t, scene, frame, config.screenDivider(), () -> { });
                c.writeAverage(frame);
                refined = c;
                return frame;
            }
            steps.step("rendering", () -> t.tilesDone() / (double) t.frameTiles());
            t.render(scene, frame, config.samples(), 0, config.screenDivider());
            return frame;
        } finally {
            t.close();
        }
    }

    /**
     * Writes each image to its hidden file (a PNG through the view transform of the config {@link #render} was
     * given), then renames them all into place, unless cancelled before.
     */
    public void write(FrameBuffer frame, Steps steps) throws IOException {
        filesWritten = 0;
        steps.step("writing the image", this::writtenFraction);
        for (int i = 0; i < images.size(); i++) {
            fileWriting = i;
            filesWritten = i;
            Path image = images.get(i), part = parts.get(i).path();
            OutputFile.keepPermissions(image, part);
            try {
                ImageWriter.writeTemporary(frame, view, image, part, this);
            } catch (InterruptedIOException e) {
                throw e;
            } catch (IOException e) {
                throw new WriteFailure(image, e);
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
                        throw new WriteFailure(images.get(0), e);
                    }
                    renamed = true; // the first is there: say so, and why the next is not
                    throw new WriteFailure(images.get(i), e, " (" + images.get(0) + " was written)");
                }
            }
            renamed = true;
        }
    }

    /**
     * Cancels the still at once (any thread): no rename follows, the hidden files are deleted now (a write
     * under way goes on into nothing and stops at its next bytes), the render's tiles not yet started are
     * skipped. Returns false, changing nothing, when it comes too late: the images are in place.
     */
    public boolean cancel() {
        Tracer t;
        synchronized (this) {
            if (renamed) {
                return false;
            }
            cancelled = true;
            parts.forEach(PartFile::delete);
            t = tracer;
        }
        if (t != null) {
            t.cancel();
        }
        return true;
    }

    /** Whether the still was cancelled. */
    @Override
    public boolean cancelled() {
        return cancelled;
    }

    @Override
    public void progress(double fraction) {
        filesWritten = fileWriting + Math.min(1, Math.max(0, fraction));
    }

    /** Whether the images are being written (the render is done). */
    public boolean writing() {
        return filesWritten >= 0;
    }

    /** Percent of the render's tiles done (0 before it starts). */
    public int percentRendered() {
        Tracer t = tracer;
        return t == null ? 0 : (int) (100L * t.tilesDone() / Math.max(1, t.frameTiles()));
    }

    /** Percent of the images written (0 before the write starts). */
    public int percentWritten() {
        return (int) (100 * writtenFraction());
    }

    private double writtenFraction() {
        return Math.max(0, filesWritten) / images.size();
    }

    private void checkCancelled() {
        if (cancelled) {
            throw new CancellationException("the still was cancelled");
        }
    }

    /** Deletes the hidden files not renamed into place, wherever their folder is now; ends the guard. */
    @Override
    public void close() {
        synchronized (this) {
            parts.forEach(PartFile::close);
        }
        guard.close();
        Tracer t = tracer;
        if (t != null) {
            t.close();
        }
    }

    /**
     * The samples an adaptive still spent, as its report says them: {@code 97.3 spp on average, 64 to 1024}; empty
     * for a still of {@code samples} a pixel or before the render.
     */
    public String samplesSpent() {
        Convergence c = refined;
        if (c == null) {
            return "";
        }
        int pixels = c.width() * c.height();
        return String.format(Locale.ROOT, "%.1f spp on average, %d to %d", c.samplesSpent() / (double) pixels,
                c.fewestSamples(), c.passes());
    }

    private static String percent(double fraction) {
        return new java.math.BigDecimal(Double.toString(100 * fraction)).round(new java.math.MathContext(6))
                .stripTrailingZeros().toPlainString();
    }

    /**
     * What a still is rendered with, as its report says it: {@code 800x600, 4 spp, phong, depth 16}, with
     * {@code threads} {@code 800x600, 4 spp, 2 threads, cook-torrance, path, depth 16}.
     */
    public static String describe(Config config, boolean threads) {
        return String.format(Locale.ROOT, "%dx%d, %s, %s%s%s, depth %d", config.displayWidth(),
                config.displayHeight(), config.adaptiveStill() ? "noise " + percent(config.noise()) + " %, at most "
                        + config.maxSamples() + " spp" : config.samples() + " spp", threads ? config.effectiveThreads() + " threads, " : "",
                config.shading().key(), config.transport().physical() ? ", " + config.transport().key() : "",
                config.recursionMax());
    }
}
