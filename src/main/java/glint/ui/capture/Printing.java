package glint.ui.capture;

import java.io.PrintWriter;
import java.io.UncheckedIOException;

/**
 * What the window prints on standard output (key C's camera block, a still's report and command): a
 * write that fails (a full disk, a closed descriptor, a pipe whose reader has gone) is found and said,
 * never swallowed. The program's standard output throws {@link UncheckedIOException} at a failed line;
 * any other writer is asked {@link PrintWriter#checkError}.
 */
final class Printing {

    private Printing() {
    }

    /** Prints {@code text} and flushes it; returns null when it was written, else why not, in one line. */
    static String print(PrintWriter out, String text) {
        try {
            out.print(text);
            out.flush();
            return out.checkError() ? "cannot write to standard output" : null;
        } catch (UncheckedIOException e) {
            return e.getMessage();
        }
    }
}
