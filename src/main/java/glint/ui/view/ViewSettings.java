package glint.ui.view;

import glint.config.Config;
import glint.config.Flags;
import glint.image.ViewTransform;
import glint.input.InputException;
import glint.render.LightTransport;
import glint.render.RenderSettings;
import glint.render.Shading;
import glint.scene.Scene;
import glint.ui.frames.ResolutionGovernor;

/**
 * What the window sees a scene with: config.properties under the scene's {@code render:} block, under the
 * command line's flags ({@link Flags#effective}); and on top, the shading, integrator, depth and view transform
 * the user picked with M, I, + and -, the exposure keys and T, which hold until the scene's or the config's
 * value for them changes. Others
 * read it; only its {@link SceneView} changes it, and starts the frame over when it does. Engine thread only.
 */
public final class ViewSettings {

    private final Flags flags;
    private Config base; // config.properties with the command line's flags
    private Config config; // the scene's settings: base under its render: block, under the flags
    private Shading shading; // the shading, integrator and depth on screen: the scene's, or the user's
    private LightTransport transport;
    private int depth;
    private ViewTransform view; // the exposure and tone on screen: the scene's, or the user's
    private String blockError = "";

    public ViewSettings(Config base, Flags flags) {
        this.flags = flags;
        this.base = base;
        this.config = base;
        this.shading = base.shading();
        this.depth = base.recursionMax();
        this.transport = base.transport();
        this.view = base.view();
    }

    /** A scene (a new one, or a new version of it) is on screen from now on. */
    void scene(Scene scene) {
        Config seen = seenWith(scene);
        if (seen.shading() != config.shading()) {
            shading = seen.shading();
        }
        if (seen.recursionMax() != config.recursionMax()) {
            depth = seen.recursionMax();
        }
        if (seen.transport() != config.transport()) {
            transport = seen.transport();
        }
        if (shading == Shading.PHONG && transport.physical()) { // the scene's new value wins
            if (seen.shading() != config.shading()) {
                transport = LightTransport.WHITTED;
            } else {
                shading = Shading.COOK_TORRANCE;
            }
        }
        if (!seen.view().equals(config.view())) {
            view = seen.view();
        }
        config = seen;
    }

    /** F5 read the config again: its settings, and the scene's block over them, replace the user's. */
    void configFile(Config newBase, Scene scene) {
        base = newBase;
        config = seenWith(scene);
        shading = config.shading();
        transport = config.transport();
        view = config.view();
        depth = config.recursionMax(); // at most max_recursion: the config loader and the block refuse more
    }

    /** The scene's settings: config.properties under its render: block, under the command line's flags. */
    public Config config() {
        return config;
    }

    /** The shading model on screen: the scene's, or the user's (M or Tab). */
    public Shading shading() {
        return shading;
    }

    /** The integrator on screen: the scene's, or the user's (key I). */
    public LightTransport transport() {
        return transport;
    }

    /** The recursion depth on screen: the scene's, or the user's (+ and -). */
    public int depth() {
        return depth;
    }

    /** The view transform on screen: the scene's, or the user's (the exposure keys and T). */
    public ViewTransform view() {
        return view;
    }

    /** Why the scene's render: block was left out (beyond the config's limits), or empty. */
    String blockError() {
        return blockError;
    }

    /** What the tracer renders with now. */
    public RenderSettings render() {
        return still().renderSettings();
    }

    /** The scene's settings with the shading, integrator and depth on screen. */
    public Config still() {
        return config.withShading(shading).withTransport(transport).withRecursionMax(depth).withView(view);
    }

    /**
     * Switches the shading model; the path and bdpt integrators go with cook-torrance only, so phong
     * brings Whitted's. Returns what the overlay says.
     */
    String toggleShading() {
        shading = shading.other();
        if (shading == Shading.PHONG && transport.physical()) {
            String was = transport.key();
            transport = LightTransport.WHITTED;
            return "shading phong, integrator whitted (" + was + " needs cook-torrance)";
        }
        return "shading " + shading.key();
    }

    /** The next integrator (whitted, path, bdpt); path and bdpt bring cook-torrance. Returns what the overlay says. */
    String toggleTransport() {
        transport = transport.next();
        if (transport.physical() && shading == Shading.PHONG) {
            shading = Shading.COOK_TORRANCE;
            return "integrator " + transport.key() + ", shading cook-torrance (" + transport.key() + " needs it)";
        }
        return "integrator " + transport.key();
    }

    /** Half a stop of exposure brighter (+1) or darker (-1), within 16 stops; returns what the overlay says. */
    String stepExposure(int step) {
        double next = Math.max(-ViewTransform.MAX_EXPOSURE, Math.min(ViewTransform.MAX_EXPOSURE,
                view.exposure() + EXPOSURE_STEP * step));
        if (next == view.exposure()) {
            return "exposure stays " + ViewTransform.stops(next) + " (from -16 to +16 stops)";
        }
        view = view.withExposure(next);
        return "exposure " + ViewTransform.stops(next);
    }

    /** The stops one key press of exposure changes. */
    public static final double EXPOSURE_STEP = 0.5;

    /** The other tone curve; returns what the overlay says. */
    String toggleTone() {
        view = view.withTone(view.tone().other());
        return "tone " + view.tone().key();
    }

    /**
     * One step up (+1) or down (-1) in depth, from 1 to the config's max_recursion; returns what the overlay
     * says.
     */
    String stepDepth(int step) {
        int max = config.limits().maxRecursion();
        int next = Math.max(1, Math.min(max, depth + step));
        if (next == depth) {
            return "depth stays " + depth + " (from 1 to " + max + ", max_recursion)";
        }
        depth = next;
        return "depth " + next;
    }

    /**
     * The settings of a still of the view (the render key): {@link #still()} at the size of --width and
     * --height, else of the scene's render: block, else of the {@code window}.
     */
    public Config still(Scene scene, ResolutionGovernor.Size window) {
        boolean sized = flags.setsSize() || scene.render().width() != null;
        return still().withSize(sized ? config.displayWidth() : window.width(),
                sized ? config.displayHeight() : window.height());
    }

    private Config seenWith(Scene scene) {
        try {
            blockError = "";
            return flags.effective(base, scene.render());
        } catch (InputException e) {
            blockError = e.getMessage();
            return base;
        }
    }
}
