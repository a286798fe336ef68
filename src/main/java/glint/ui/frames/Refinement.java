package glint.ui.frames;

import glint.config.Config;
import glint.render.LightTransport;

/**
 * How far the window refines a view at rest, and in which pattern of samples. Whitted's refinement
 * is the still: the passes are the samples of the still's stratified pattern, and after the last the
 * image is the still. The path and bdpt integrators' refine each pixel until its noise is below the
 * config's threshold ({@link Config#windowNoise}) or it has {@code max_samples} ({@link glint.render.Convergence}),
 * in patterns of {@link #PATH_PATTERN} stratified samples one after another (pass p is sample p mod the
 * pattern of frame p / the pattern).
 */
public final class Refinement {

    /** The path's passes come in stratified patterns of this many samples ({@link glint.render.Convergence#PATTERN}). */
    public static final int PATH_PATTERN = glint.render.Convergence.PATTERN;

    private Refinement() {
    }

    /** How many passes the view at rest accumulates. */
    public static int passes(Config onScreen) {
        return onScreen.transport().physical() ? onScreen.maxSamples() : onScreen.samples();
    }

    /** The noise a pixel stops at: the config's for the path and bdpt, none (0) for Whitted's still. */
    public static double threshold(Config onScreen) {
        return onScreen.transport().physical() ? onScreen.windowNoise() : 0;
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
