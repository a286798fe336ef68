package glint.ui.view;

import java.io.PrintWriter;

/**
 * What the overlay says besides the figures: the last thing done ({@link #note}), the last load or save error
 * ({@link #error}), and whether either changed since the overlay last showed them. Engine thread only, except
 * {@link #error()}, which any thread may read.
 */
public final class StatusLine {

    private final PrintWriter err;
    private String message = "";
    private volatile String error = ""; // written on the engine thread only
    private boolean changed;

    /** @param err where a new error is printed, once */
    public StatusLine(PrintWriter err) {
        this.err = err;
    }

    /** Standard error, where what failed is said besides the overlay. */
    public PrintWriter log() {
        return err;
    }

    /** The overlay says {@code text} from the next frame on. */
    public void note(String text) {
        message = text;
        changed = true;
    }

    /** The overlay shows {@code problem} (empty: no error); a new one is printed on standard error as well. */
    public void error(String problem) {
        if (!problem.isEmpty() && !problem.equals(error)) {
            err.println(problem);
        }
        error = problem;
        changed = true;
    }

    /** Something else on the overlay changed (settings, speed, a failed frame): show it again. */
    public void changed() {
        changed = true;
    }

    /** Whether the overlay is behind: something changed since {@link #shown}. */
    public boolean isChanged() {
        return changed;
    }

    /** The overlay shows everything as it is now. */
    public void shown() {
        changed = false;
    }

    public String message() {
        return message;
    }

    /** The last load error as {@code file:line:col: message}, or empty (any thread). */
    public String error() {
        return error;
    }
}
