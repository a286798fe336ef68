package glint.app;

import glint.input.LastWords;
import java.io.PrintWriter;

/**
 * An error that ends a thread of the program other than the main one (memory running out in the
 * progress thread, a bug in a thread of its own) is one line on standard error, {@code glint: ...}, never a
 * stack trace, and the program's exit status is then 1. Memory running out is said once, whichever
 * thread meets it first (the main thread usually meets it too). Printing a line takes a little memory:
 * when even that is not there, the line is printed when the run ends.
 */
final class ThreadFailures {

    private final PrintWriter err;
    private volatile boolean failed;
    private volatile boolean outOfMemorySaid;
    private volatile String unsaid; // a line that could not be printed when it happened

    ThreadFailures(PrintWriter err) {
        this.err = err;
    }

    /** Reports every thread's uncaught error here from now on (the whole program: called once, by main). */
    static ThreadFailures install(PrintWriter err) {
        ThreadFailures failures = new ThreadFailures(err);
        Thread.setDefaultUncaughtExceptionHandler(failures::uncaught);
        return failures;
    }

    /** A thread ended on {@code e}: one line, and the program will end with status 1. */
    void uncaught(Thread thread, Throwable e) {
        failed = true;
        if (e instanceof OutOfMemoryError) {
            reserve = null;
        }
        try {
            say(e instanceof OutOfMemoryError ? Main.outOfMemory(e)
                    : "glint: unexpected error on " + thread.getName() + ": " + e);
        } catch (Throwable again) { // no memory left even for the line
            unsaid = Main.OUT_OF_MEMORY;
        }
    }

    /** Prints the program's line that memory ran out, unless a thread has said it already. */
    void outOfMemory(Throwable e) {
        if (!outOfMemorySaid) {
            reserve = null;
            String line;
            try {
                line = Main.outOfMemory(e);
            } catch (OutOfMemoryError again) {
                line = Main.OUT_OF_MEMORY;
            }
            say(line);
        }
    }

    /** The exit status of a run that returned {@code status}: 1 if a thread failed; says what was not said yet. */
    int status(int status) {
        String line = unsaid;
        if (line != null) {
            unsaid = null;
            say(line);
        }
        return failed && status == Main.OK ? Main.FAILURE : status;
    }

    private synchronized void say(String line) {
        boolean memory = line.startsWith(Main.OUT_OF_MEMORY_START);
        if (memory && outOfMemorySaid) {
            return;
        }
        outOfMemorySaid |= memory;
        if (memory) {
            reserve = null; // room to say it
        }
        try {
            err.println(line);
            err.flush();
        } catch (OutOfMemoryError e) { // the line of memory running out, made before it ran out
            outOfMemorySaid = true;
            OUT_OF_MEMORY.sayWithoutMemory();
        }
    }

    /** {@link Main#OUT_OF_MEMORY}, encoded while there is memory. */
    private static final LastWords OUT_OF_MEMORY = new LastWords(Main.OUT_OF_MEMORY);

    /** Memory held back so that, when the heap is full, there is room to say so. */
    private volatile byte[] reserve = new byte[RESERVE_BYTES];
    static final int RESERVE_BYTES = 64 * 1024;

}
