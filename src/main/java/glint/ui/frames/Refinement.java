package glint.ui.frames;

import glint.config.Config;
import glint.render.LightTransport;

/**
 * How far the window refines a view at rest, and in which pattern of samples. Whitted's refinement
 * is the still: the passes are the samples of the still's stratified pattern, and after the last the
 * image is the still. The path integrator's goes on for as long as the user watches (up to
 * {@link #PATH_PASSES}), in patterns of {@link #PATH_PATTERN} stratified samples one after another
 * (pass p is sample p mod the pattern of frame p / the pattern).
 */
public final class Refinement {

    /** The most passes the window accumulates with the path integrator: 65536 samples a pixel, noise well under 1 %. */
    static final int PATH_PASSES = 1 << 16;
    /**
     * The path's passes come in stratified patterns of this many samples (8 x 8): any prefix of one is
     * unbiased, and a finished one is as good as a still of 64 samples. Chosen, not measured.
     */
    public static final int PATH_PATTERN = 64;

    private Refinement() {
    }

    /** How many passes the view at rest accumulates. */
    public static int passes(Config onScreen) {
        return onScreen.transport().physical() ? PATH_PASSES : onScreen.samples();
    }

    /** How many samples one pattern holds, of which a pass is one. */
    public static int pattern(Config onScreen) {
        return onScreen.transport().physical() ? PATH_PATTERN : onScreen.samples();
    }

    /** How many of {@code wanted} passes from {@code done} may go in one call: never across a pattern's end. */
    public static int inOneCall(int wanted, int done, int pattern) {
        return Math.max(1, Math.min(wanted, pattern - done % pattern));
    }
}
