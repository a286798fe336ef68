package glint.app;

import glint.still.OutputFile;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.charset.Charset;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.BooleanSupplier;

/**
 * Standard output as a Unix tool writes it: every line goes out at once, and a write that fails (a
 * full disk, a closed descriptor, a reader that has gone away) throws {@link Failure} at the line that
 * met it, where {@link java.io.PrintStream} and {@link PrintWriter} would swallow it and go on. Lines
 * ({@code println}), {@code printf} and {@code flush} are checked; once a write has failed, every later
 * one throws too. {@link Main} turns a failure into its message and exit status.
 */
final class Output extends PrintWriter {

    /** Why a line could not be written: {@code cannot write to standard output: No space left on device}. */
    static final class Failure extends UncheckedIOException {
        private final boolean readerGone;
        private final String after;

        Failure(IOException cause, boolean readerGone, String after) {
            super("cannot write to standard output: " + OutputFile.reason(cause) + after, cause);
            this.readerGone = readerGone;
            this.after = after;
        }

        /** Whether the output was a pipe whose reader has gone ({@code | head -1}): not an error to report. */
        boolean readerGone() {
            return readerGone;
        }

        /** The same failure, its message saying what was done before it ({@code "the image out.png was written"}). */
        Failure after(String done) {
            return new Failure(getCause(), readerGone, after + " (" + done + ")");
        }
    }

    /** The stream under the writer, which keeps the first error it met (the writer keeps only a flag). */
    private static final class Recorder extends FilterOutputStream {
        private volatile IOException failure;

        Recorder(OutputStream out) {
            super(out);
        }

        @Override
        public void write(int b) throws IOException {
            try {
                out.write(b);
            } catch (IOException e) {
                throw remember(e);
            }
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            try {
                out.write(b, off, len);
            } catch (IOException e) {
                throw remember(e);
            }
        }

        @Override
        public void flush() throws IOException {
            try {
                out.flush();
            } catch (IOException e) {
                throw remember(e);
            }
        }

        private IOException remember(IOException e) {
            if (failure == null) {
                failure = e;
            }
            return e;
        }
    }

    private final Recorder recorder;
    private final BooleanSupplier isPipe;

    /**
     * @param isPipe whether the stream is a pipe or a socket, asked once a write has failed: a failed
     *               write to a pipe means its reader has gone
     */
    Output(OutputStream stream, BooleanSupplier isPipe) {
        this(new Recorder(stream), isPipe, new AtomicBoolean(), null);
    }

    /**
     * @param noted  whether a character the locale cannot carry was said already, by this stream or another
     * @param noteTo where that is said ({@link LocaleWriter})
     */
    private Output(Recorder recorder, BooleanSupplier isPipe, AtomicBoolean noted, PrintWriter noteTo) {
        super(new java.io.BufferedWriter(LocaleWriter.of(recorder, Charset.defaultCharset(), noted, noteTo)), true);
        this.recorder = recorder;
        this.isPipe = isPipe;
    }

    /**
     * The program's standard output (file descriptor 1): in the locale's charset, a character it cannot carry
     * written as its code and said once on {@code err} ({@link LocaleWriter}).
     */
    static Output standard(AtomicBoolean noted, PrintWriter err) {
        return new Output(new Recorder(new FileOutputStream(FileDescriptor.out)), Output::standardOutputIsPipe, noted, err);
    }

    @Override
    public void println() {
        super.println();
        check();
    }

    @Override
    public PrintWriter format(String format, Object... args) {
        super.format(format, args);
        check();
        return this;
    }

    @Override
    public PrintWriter format(Locale locale, String format, Object... args) {
        super.format(locale, format, args);
        check();
        return this;
    }

    @Override
    public void flush() {
        super.flush();
        check();
    }

    /** Whether a write has failed so far. */
    boolean failed() {
        return recorder.failure != null;
    }

    /** Throws {@link Failure} if a write has failed. */
    void check() {
        IOException e = recorder.failure;
        if (e != null) {
            throw new Failure(e, "Broken pipe".equals(e.getMessage()) || isPipe.getAsBoolean(), "");
        }
    }

    /** Whether file descriptor 1 is a pipe or a socket (Linux: what /proc/self/fd/1 links to); false when unknown. */
    private static boolean standardOutputIsPipe() {
        try {
            String target = Files.readSymbolicLink(Path.of("/proc/self/fd/1")).toString();
            return target.startsWith("pipe:") || target.startsWith("socket:");
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            return false;
        }
    }
}
