package glint.ui.engine;

import glint.render.RenderException;

/**
 * The engine's record of frames that failed to render (a worker threw, memory ran out): what the overlay
 * says, when to try again, and what standard error says once at the start and once at the end of a run
 * of failures, not once a frame.
 */
final class RenderFaults {

    /** After a frame failed to render, it is tried again this much later (sooner would only spin). */
    static final long RETRY_NANOS = 500_000_000L;

    private int failedFrames; // since the last good frame
    private String overlayLine = "";
    private long retryAt;

    /**
     * Records a failure at time {@code now}; returns the line for standard error when it starts a run of
     * failures, or null.
     */
    String failed(Throwable e, long now) {
        String why = "render failed: " + (e instanceof RenderException ? e.getMessage()
                : e instanceof OutOfMemoryError ? "out of memory (" + e.getMessage() + ")" : e.toString());
        failedFrames++;
        overlayLine = why + (failedFrames == 1 ? "" : " (" + failedFrames + " tries)") + "; trying again";
        retryAt = now + RETRY_NANOS;
        return failedFrames == 1 ? "glint: " + why + "; trying again every " + RETRY_NANOS / 1_000_000 + " ms"
                : null;
    }

    /** Records a good frame; returns the line for standard error when it ends a run of failures, or null. */
    String rendered() {
        if (failedFrames == 0) {
            return null;
        }
        String line = "glint: rendering works again after " + failedFrames + " failed "
                + (failedFrames == 1 ? "try" : "tries");
        failedFrames = 0;
        overlayLine = "";
        return line;
    }

    /** The overlay's line while frames fail, or empty. */
    String overlayLine() {
        return overlayLine;
    }

    /** When the next try is due (meaningful after a failure; in the past once it is due). */
    long retryAt() {
        return retryAt;
    }
}
