package glint.app;

import glint.render.Tracer;
import java.io.PrintWriter;
import java.util.Locale;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * Shows how far a long still render is, on standard error: nothing for the first two seconds, then
 * percent done and time left, as a bar redrawn in place on a terminal or as a plain line at every
 * further tenth otherwise (a log, a pipe). Read from the tracer's tile count four times a second.
 */
final class Progress implements AutoCloseable {

    /** Renders shorter than this show nothing. */
    static final long QUIET_NANOS = 2_000_000_000L;
    private static final int BAR_WIDTH = 30;

    private final Tracer tracer;
    private final PrintWriter err;
    private final boolean terminal;
    private final long start = System.nanoTime();
    private final ScheduledExecutorService timer;
    private int tenthsShown = -1;
    private boolean barShown;

    private Progress(Tracer tracer, PrintWriter err, boolean terminal) {
        this.tracer = tracer;
        this.err = err;
        this.terminal = terminal;
        this.timer = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "glint-progress");
            t.setDaemon(true);
            return t;
        });
        timer.scheduleAtFixedRate(this::show, 250, 250, TimeUnit.MILLISECONDS);
    }

    /** Starts showing the progress of the tracer's frame; a bar when standard error is a terminal. */
    static Progress start(Tracer tracer, PrintWriter err) {
        return new Progress(tracer, err, System.console() != null);
    }

    private synchronized void show() {
        long elapsed = System.nanoTime() - start;
        if (elapsed < QUIET_NANOS) {
            return;
        }
        double fraction = Math.min(1, tracer.tilesDone() / (double) tracer.frameTiles());
        if (terminal) {
            err.print("\r" + bar(fraction, elapsed));
            err.flush();
            barShown = true;
        } else {
            int tenths = (int) (fraction * 10);
            if (tenths > tenthsShown && fraction < 1) {
                tenthsShown = tenths;
                err.println(line(fraction, elapsed));
            }
        }
    }

    /** Stops showing; a bar on the terminal is cleared so the next line starts clean. */
    @Override
    public synchronized void close() {
        timer.shutdownNow();
        if (barShown) {
            err.print("\r" + " ".repeat(BAR_WIDTH + 32) + "\r");
            err.flush();
            barShown = false;
        }
    }

    /** A plain progress line: {@code rendering: 25% done, about 30 s left}. */
    static String line(double fraction, long elapsedNanos) {
        return String.format(Locale.ROOT, "rendering: %d%% done, %s", (int) (fraction * 100), left(fraction, elapsedNanos));
    }

    /** A progress bar: {@code [#######                       ] 25%, about 30 s left}. */
    static String bar(double fraction, long elapsedNanos) {
        int filled = (int) (fraction * BAR_WIDTH);
        return String.format(Locale.ROOT, "[%s%s] %3d%%, %s", "#".repeat(filled), " ".repeat(BAR_WIDTH - filled),
                (int) (fraction * 100), left(fraction, elapsedNanos));
    }

    /** The time left if the rest goes as fast as the part done: {@code about 3 min 20 s left}. */
    static String left(double fraction, long elapsedNanos) {
        if (fraction <= 0) {
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
