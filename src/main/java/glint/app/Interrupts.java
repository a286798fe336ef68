package glint.app;

import java.io.PrintWriter;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * A signal that ends the program (Ctrl-C's SIGINT, SIGTERM, SIGHUP, and the others of
 * {@link #OTHER_ENDING_SIGNALS}) during a headless run: cancels the work it watches at once (a still's
 * render or write, whose hidden files its cancel deletes: {@link glint.still.StillRun#cancel}; the frames
 * of {@code --bench}) and gives the main thread a moment to stop and clean up, so that no partial image is
 * left and no stack trace is printed. A still's rename and its cancel exclude each other: either the image
 * was written (and the program says so) or it was not (and an existing one is as it was). Installed for
 * the length of one run; the JVM exits with 128 + the signal's number.
 */
final class Interrupts implements AutoCloseable {

    /** The work a signal stops. */
    @FunctionalInterface
    interface Work {
        /** Stops the work at once; returns false when it came too late (the image is in place). */
        boolean cancel();
    }

    /** How long the JVM waits for the main thread to stop before it exits anyway. */
    static final long WAIT_MILLIS = 2000;

    private final Thread hook = new Thread(this::stop, "glint-interrupt");
    private final CountDownLatch finished = new CountDownLatch(1);
    private final AtomicBoolean reported = new AtomicBoolean();
    private final PrintWriter err;
    private final String message;
    private volatile Work work;
    private volatile Runnable clearLine = () -> { };
    private volatile boolean stopping;

    private Interrupts(PrintWriter err, String message) {
        this.err = err;
        this.message = message;
    }

    /**
     * Installs the hook for one run.
     *
     * @param message what to print when stopped before anything was written, by the main thread or,
     *                if it does not stop in time (a tile that takes long), by the hook
     */
    static Interrupts install(PrintWriter err, String message) {
        Interrupts interrupts = new Interrupts(err, message);
        Runtime.getRuntime().addShutdownHook(interrupts.hook);
        return interrupts;
    }

    /**
     * Signals whose default action ends the JVM without running its shutdown hooks (which the JVM
     * runs only for SIGINT, SIGTERM and SIGHUP): a run they stop would leave its temporary file.
     * SIGPROF and SIGVTALRM are left alone: sampling profilers (async-profiler, perf's JVM agents)
     * tick with them. The JVM keeps SIGSEGV, SIGBUS, SIGFPE, SIGILL and SIGQUIT for itself (sent
     * with kill, the first four crash it with its fatal-error report), and SIGABRT is its own way
     * to crash; SIGXFSZ it ignores, so that a write beyond {@code ulimit -f} fails and is reported.
     */
    static final List<String> OTHER_ENDING_SIGNALS = List.of("USR1", "USR2", "ALRM", "XCPU", "POLL", "PWR",
            "STKFLT", "SYS", "TRAP");

    /**
     * Makes the {@link #OTHER_ENDING_SIGNALS} end the program as SIGTERM does: hooks run, status
     * 128 + the signal's number. Called once by the program's {@code main}; a signal this platform
     * does not have, or the JVM keeps for itself, is left as it is.
     */
    static void handleOtherEndingSignals() {
        for (String name : OTHER_ENDING_SIGNALS) {
            try {
                sun.misc.Signal.handle(new sun.misc.Signal(name), signal -> System.exit(128 + signal.getNumber()));
            } catch (IllegalArgumentException | UnsupportedOperationException e) {
                // not a signal here, or used by the JVM
            }
        }
    }

    /** The work to stop if the program is stopped; stopped at once if it is being stopped already. */
    void watch(Work stoppable) {
        this.work = stoppable;
        if (stopping) {
            stoppable.cancel();
        }
    }

    /** What the shutdown hook does; also callable directly. */
    void stop() {
        stopping = true;
        Work w = work;
        boolean lost = w == null || w.cancel(); // after a rename under way, before any other
        try {
            finished.await(WAIT_MILLIS, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        if (lost) {
            report(message);
        }
    }

    /** What clears the line before the report is printed: a progress bar on the terminal, so it starts a line of its own. */
    void clearLineWith(Runnable clear) {
        this.clearLine = clear;
    }

    /** Prints the line saying the run was stopped, once, whoever comes first, on a line of its own. */
    void report(String line) {
        if (reported.compareAndSet(false, true)) {
            clearLine.run();
            err.println(line);
            err.flush();
        }
    }

    /** The run is over: the hook is removed (or, if the JVM is already stopping, let go). */
    @Override
    public void close() {
        finished.countDown();
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException e) {
            // shutting down: the hook runs and returns at once
        }
    }
}
