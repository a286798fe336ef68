package glint.app;

import java.io.PrintWriter;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.function.DoubleSupplier;
import java.util.function.LongSupplier;

/**
 * Shows how far a long still is, on standard error, step by step (reading and preparing the scene,
 * rendering, writing the image): nothing for the first two seconds of the run, then each step as
 * it begins and, for a step that knows how far it is, percent done and (from a tenth on) time left, as a bar redrawn
 * in place on a terminal or as a plain line at every further tenth otherwise (a log, a pipe), and
 * at least every 10 seconds while nothing changes. Read four times a second, by a thread of its own
 * that allocates nothing between two reads (no executor's queue): memory running out while it shows
 * a line ends it like any thread of the program, in one line ({@link ThreadFailures}).
 */
final class Progress implements AutoCloseable {

    /** Runs shorter than this show nothing. */
    static final long QUIET_NANOS = 2_000_000_000L;
    private static final int BAR_WIDTH = 30;
    /** The widest line a terminal shows, cleared before the next. */
    private static final int LINE_WIDTH = BAR_WIDTH + 60;

    /** A plain line is printed at least this often while a step goes on, even with no new tenth. */
    static final long HEARTBEAT_NANOS = 10_000_000_000L;

    private final PrintWriter err;
    private final boolean terminal;
    private final LongSupplier clock;
    private final long start;
    private final Thread timer;
    private volatile boolean closed;
    private long lastLine;
    private String step;
    private DoubleSupplier fraction;
    private long stepStart;
    private boolean stepShown;
    private int tenthsShown = -1;
    private boolean barShown;

    private Progress(PrintWriter err, boolean terminal, LongSupplier clock, boolean timed) {
        this.err = err;
        this.terminal = terminal;
        this.clock = clock;
        this.start = clock.getAsLong();
        this.timer = timed ? new Thread(this::showEveryQuarterSecond, "glint-progress") : null;
        if (timer != null) {
            timer.setDaemon(true);
            timer.start();
        }
    }

    private void showEveryQuarterSecond() {
        long next = System.nanoTime();
        while (!closed) {
            next += TimeUnit.MILLISECONDS.toNanos(250);
            for (long wait = next - System.nanoTime(); wait > 0 && !closed; wait = next - System.nanoTime()) {
                LockSupport.parkNanos(this, wait);
            }
            if (!closed) {
                show();
            }
        }
    }

    /** Starts the clock of the run; a bar when standard error is a terminal. */
    static Progress start(PrintWriter err) {
        return new Progress(err, standardErrorIsATerminal(), System::nanoTime, true);
    }

    /**
     * Whether standard error is a terminal, which the bar is drawn on: where the system tells what file it is
     * (Linux's {@code /proc/self/fd/2}), that file; elsewhere whether the program has a console. Standard error
     * sent to a file or a pipe gets plain lines, whatever standard input and output are.
     */
    static boolean standardErrorIsATerminal() {
        return isTerminal(STANDARD_ERROR, System.console() != null);
    }

    private static final java.nio.file.Path STANDARD_ERROR = java.nio.file.Path.of("/proc/self/fd/2");

    /** Whether the file {@code link} (a descriptor's link) is a terminal; {@code otherwise} where it cannot be told. */
    static boolean isTerminal(java.nio.file.Path link, boolean otherwise) {
        try {
            String file = java.nio.file.Files.readSymbolicLink(link).toString();
            return file.startsWith("/dev/pts/") || file.startsWith("/dev/tty") || file.equals("/dev/console");
        } catch (java.io.IOException | UnsupportedOperationException | SecurityException e) {
            return otherwise;
        }
    }

    /** A bar, as on a terminal, on the given clock, shown only when {@link #show} is called (for tests). */
    static Progress onTerminal(PrintWriter err, LongSupplier clock) {
        return new Progress(err, true, clock, false);
    }

    /** Plain lines on the given clock, shown only when {@link #show} is called (for tests). */
    static Progress onClock(PrintWriter err, LongSupplier clock) {
        return new Progress(err, false, clock, false);
    }

    /**
     * The run goes on to the next step.
     *
     * @param done the fraction of the step done, from 0 to 1, or null when the step cannot tell
     */
    synchronized void step(String name, DoubleSupplier done) {
        step = name;
        fraction = done;
        stepStart = clock.getAsLong();
        stepShown = false;
        tenthsShown = -1;
    }

    /** Shows the step as it is now; called four times a second. */
    synchronized void show() {
        long now = clock.getAsLong();
        if (step == null || now - start < QUIET_NANOS) {
            return;
        }
        long elapsed = now - stepStart;
        boolean heartbeat = stepShown && now - lastLine >= HEARTBEAT_NANOS; // a long stretch with nothing new
        if (fraction == null) {
            if (terminal) {
                redraw(String.format(Locale.ROOT, "%s... %d s", step, elapsed / 1_000_000_000L));
            } else if (!stepShown || heartbeat) {
                print(stepShown ? String.format(Locale.ROOT, "%s... %d s so far", step, elapsed / 1_000_000_000L)
                        : step + "...", now);
            }
            stepShown = true;
            return;
        }
        double f = Math.max(0, Math.min(1, fraction.getAsDouble()));
        if (terminal) {
            redraw(step + " " + bar(f, elapsed));
        } else {
            int tenths = (int) (f * 10);
            if ((tenths > tenthsShown || heartbeat) && f < 1) {
                tenthsShown = Math.max(tenths, tenthsShown);
                print(line(step, f, elapsed), now);
            }
        }
        stepShown = true;
    }

    private void print(String line, long now) {
        err.println(line);
        lastLine = now;
    }

    private void redraw(String text) {
        String shown = text.length() > LINE_WIDTH ? text.substring(0, LINE_WIDTH) : text;
        err.print("\r" + shown + " ".repeat(LINE_WIDTH - shown.length()));
        err.flush();
        barShown = true;
    }

    /** Stops showing; a bar on the terminal is cleared so the next line starts clean. */
    @Override
    public synchronized void close() {
        closed = true;
        if (timer != null) {
            LockSupport.unpark(timer);
        }
        step = null;
        clearBar();
    }

    /** A line of its own on standard error, never on the bar's: a bar shown is cleared first, and drawn again later. */
    synchronized void note(String line) {
        clearBar();
        err.println(line);
        err.flush();
    }

    private void clearBar() {
        if (barShown) {
            err.print("\r" + " ".repeat(LINE_WIDTH) + "\r");
            err.flush();
            barShown = false;
        }
    }

    /** A plain progress line of the render: {@code rendering: 25% done, about 30 s left}. */
    static String line(double fraction, long elapsedNanos) {
        return line("rendering", fraction, elapsedNanos);
    }

    /** A plain progress line of a step: {@code writing the image: 25% done, about 30 s left}. */
    static String line(String step, double fraction, long elapsedNanos) {
        return String.format(Locale.ROOT, "%s: %d%% done, %s", step, (int) (fraction * 100), left(fraction, elapsedNanos));
    }

    /** A progress bar: {@code [#######                       ] 25%, about 30 s left}. */
    static String bar(double fraction, long elapsedNanos) {
        int filled = (int) (fraction * BAR_WIDTH);
        return String.format(Locale.ROOT, "[%s%s] %3d%%, %s", "#".repeat(filled), " ".repeat(BAR_WIDTH - filled),
                (int) (fraction * 100), left(fraction, elapsedNanos));
    }

    /**
     * The share of a step done before its time left is estimated: the first tiles are too few to tell the
     * pace of the whole (the tracer hands them out spread over the frame, so from a tenth on they do).
     */
    static final double ESTIMATE_FROM = 0.1;

    /** The time left if the rest goes as fast as the part done: {@code about 3 min 20 s left}. */
    static String left(double fraction, long elapsedNanos) {
        if (fraction < ESTIMATE_FROM) {
            return "time left not known yet";
        }
        long seconds = Math.round(elapsedNanos / 1e9 * (1 - fraction) / fraction);
        if (seconds < 60) {
            return "about " + seconds + " s left";
        }
        if (seconds < 3600) {
            return "about " + seconds / 60 + " min " + seconds % 60 + " s left";
        }
        return "about " + seconds / 3600 + " h " + seconds % 3600 / 60 + " min left";
    }
}
