package glint.input;

import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;

/**
 * A line said when the Java heap is full: encoded while there is memory, and, when printing it the usual
 * way runs out of memory too, written straight to standard error, which takes none.
 */
public final class LastWords {

    private static final FileOutputStream STANDARD_ERROR = new FileOutputStream(FileDescriptor.err);

    private final String line;
    private final byte[] bytes;

    public LastWords(String line) {
        this.line = line;
        this.bytes = (line + System.lineSeparator()).getBytes(StandardCharsets.UTF_8);
    }

    public String line() {
        return line;
    }

    /** Prints the line to {@code err}; straight to standard error if memory runs out doing so. */
    public void say(PrintWriter err) {
        try {
            err.println(line);
            err.flush();
        } catch (OutOfMemoryError e) {
            sayWithoutMemory();
        }
    }

    /** Writes the line straight to standard error, taking no memory of the heap. */
    public void sayWithoutMemory() {
        try {
            STANDARD_ERROR.write(bytes);
        } catch (IOException | RuntimeException | OutOfMemoryError e) {
            // nothing left to say it with
        }
    }
}
