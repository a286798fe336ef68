package glint.ui.frames;

import java.io.PrintWriter;
import java.util.Locale;

/**
 * How many still passes the window traces in one go. A pass of one sample a pixel costs the tracer more
 * per sample than a still's many samples a pixel (work per row of a tile, done once per call), and each
 * one shown is encoded and painted; so while passes come faster than the interval, the window traces
 * about an interval's worth of them in one call and shows their running average once. The first pass is
 * always alone (the image comes at once); with an interval of 0 every pass is. Also times the
 * refinement for the debug line.
 */
public final class RefinePacing {

    /** The most passes traced in one go. */
    static final int MOST_PASSES = 16;

    /** While refining, the window shows a new image this many times less often than it flies at most. */
    static final int FRAMES_PER_CALL = 2;

    private long interval;
    private double nanosPerPass; // of the last call
    private int timedFrom = -1; // the first pass timed for the debug line
    private long timedStart;

    /**
     * The window's interval at {@code targetFps}: {@link #FRAMES_PER_CALL} frames' time (at 30 frames a second,
     * 67 ms: 15 images a second while refining, and a key waits at most about that long).
     */
    public static long windowInterval(double targetFps) {
        return (long) (FRAMES_PER_CALL * 1e9 / targetFps);
    }

    /** Traces about {@code nanos} of passes in one go (0: one at a time). */
    public void interval(long nanos) {
        this.interval = Math.max(0, nanos);
    }

    /** How many passes to trace in one go from pass {@code pass} of {@code samples}, starting at {@code now}. */
    public int passes(int pass, int samples, long now) {
        if (pass == 0) {
            timedFrom = -1;
        }
        if (timedFrom < 0 && pass >= samples / 4 && pass > 0) { // leaves the first quarter out: the JIT's warm-up
            timedFrom = pass;
            timedStart = now;
        }
        if (interval == 0 || pass == 0 || nanosPerPass <= 0) {
            return 1;
        }
        long wanted = Math.max(1, Math.min(MOST_PASSES, Math.round(interval / nanosPerPass)));
        return (int) Math.min(wanted, samples - pass);
    }

    /**
     * Passes up to {@code done} (of {@code samples}), {@code count} of them in this call, went from {@code start}
     * to {@code end}; once the last is done, prints the refinement's timing to {@code debug} (debug=true;
     * null: not).
     */
    public void passesDone(int done, int count, int samples, long start, long end, ResolutionGovernor.Size size,
                    PrintWriter debug) {
        nanosPerPass = (end - start) / (double) count;
        if (done == samples && debug != null && timedFrom > 0) {
            int timed = samples - timedFrom;
            debug.println(String.format(Locale.ROOT, "glint: window refined %dx%d to %d samples: %.2f ms a pass"
                    + " (the last %d)", size.width(), size.height(), samples, (end - timedStart) / 1e6 / timed, timed));
        }
    }
}
