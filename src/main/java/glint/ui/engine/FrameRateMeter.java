package glint.ui.engine;

/**
 * Frames per second over the frames rendered back to back: the count of frames in the last second
 * or so, divided by the time they took. A pause (the engine idle) starts a new measurement, so that
 * waiting never reads as a low frame rate.
 */
final class FrameRateMeter {

    /** Length of the measuring window. */
    static final long WINDOW_NANOS = 1_000_000_000L;

    private long windowStart;
    private int framesInWindow;
    private double fps = Double.NaN;
    private boolean running;

    /** A frame was shown at {@code now}. */
    void frame(long now) {
        if (!running) {
            running = true;
            windowStart = now;
            framesInWindow = 0;
            return; // the first frame after a pause only starts the clock
        }
        framesInWindow++;
        long elapsed = now - windowStart;
        if (elapsed > 0 && (elapsed >= WINDOW_NANOS || Double.isNaN(fps) && framesInWindow >= 2)) {
            fps = framesInWindow * 1e9 / elapsed;
            if (elapsed >= WINDOW_NANOS) {
                windowStart = now;
                framesInWindow = 0;
            }
        }
    }

    /** The engine went idle. */
    void pause() {
        running = false;
        fps = Double.NaN;
    }

    /** Whether frames are being rendered back to back. */
    boolean isRunning() {
        return running;
    }

    /** The current rate, NaN when idle or not yet known. */
    double fps() {
        return fps;
    }

    /** Whether the last call to {@link #frame} closed a measuring window (time for a debug line). */
    boolean windowClosed() {
        return running && framesInWindow == 0 && !Double.isNaN(fps);
    }
}
