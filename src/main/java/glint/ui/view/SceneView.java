package glint.ui.view;

import glint.config.Config;
import glint.math.Vector3d;
import glint.render.RenderScene;
import glint.scene.Camera;
import glint.scene.Scene;
import glint.ui.input.CameraController;
import glint.ui.input.InputFrame;

/**
 * What the window shows: the scene, the camera flying through it, the settings it is seen with, the size
 * of the window's drawing area, the scene compiled for them, and how far the still refinement of the view
 * has come. The camera, the settings and the size change only through this class, which starts the frame
 * over ({@link #invalidate}) whenever they do; others read them ({@link #controller()}, {@link #settings()},
 * the {@link FrameSize}). Engine thread only, except {@link #camera()} and {@link #sceneNow()}, which any
 * thread may read.
 */
public final class SceneView {

    private final ViewSettings seen; // the scene's settings, the user's shading and depth
    private final CameraController controller;
    private final FrameSize size; // the window's drawing area and its frame budget under the settings' limits
    private final StatusLine status;
    private final CompiledScenes compiledScenes = new CompiledScenes();
    private Scene scene;
    private Camera fileCamera;
    private RenderScene compiled; // null: compile again before the next frame
    private boolean needFrame = true;
    private boolean retoned; // the view transform changed: the frame on screen is to be encoded again
    private int passesDone;

    private volatile Camera cameraNow;
    private volatile Scene sceneNow;

    /**
     * A view with no scene yet, whose window is {@code size} (its frame budget set under the settings'
     * limits): {@link #show} a scene before the first frame.
     */
    public SceneView(ViewSettings seen, CameraController controller, FrameSize size, StatusLine status) {
        this.seen = seen;
        this.controller = controller;
        this.size = size;
        this.status = status;
        size.check(seen.config().limits());
    }

    /**
     * Shows a new scene. The camera takes the file's pose when asked or when the file's camera
     * changed; otherwise the user's view stays where it is.
     */
    public void show(Scene newScene, boolean resetCamera) {
        if (resetCamera || !newScene.camera().equals(fileCamera)) {
            controller.reset(newScene.camera());
        }
        fileCamera = newScene.camera();
        seen.scene(newScene);
        status.error(seen.blockError());
        scene = newScene;
        sceneNow = newScene;
        cameraNow = controller.camera();
        invalidate();
    }

    /** Home: back to the scene file's camera. */
    public void home() {
        goTo(fileCamera);
    }

    /** Keys 1 to 9: the camera jumps to {@code camera} (a view of the scene). */
    public void goTo(Camera camera) {
        controller.reset(camera);
        cameraMoved();
    }

    /** L: the roll taken out of the camera, if it has any. */
    public void level() {
        if (controller.level()) {
            cameraMoved();
        }
    }

    /** One interval of input flies the camera; returns whether it moved (then the view is drawn anew). */
    public boolean fly(InputFrame in) {
        boolean moved = controller.apply(in);
        if (moved) {
            cameraMoved();
        }
        return moved;
    }

    /** ] (+1) or [ (-1): the lens's aperture a step wider or narrower; returns what the overlay says. */
    public String stepAperture(int step) {
        if (controller.stepAperture(step)) {
            cameraMoved();
        }
        return controller.lensNote();
    }

    /**
     * A click: the lens focused on {@code point}, the point under the mouse, or left as it is when there is
     * none (the sky); returns what the overlay says. A pinhole keeps the focus for when its aperture opens,
     * silently and without drawing anew, as its picture does not depend on it: returns null.
     */
    public String focusOn(Vector3d point) {
        boolean lens = cameraNow.aperture() > 0;
        if (point == null) {
            return lens ? "nothing under the mouse to focus on; " + controller.lensNote() : null;
        }
        if (controller.focusOn(point)) {
            if (lens) {
                cameraMoved();
            } else {
                cameraNow = controller.camera();
            }
        }
        return lens ? controller.lensNote() : null;
    }

    /** M or Tab: the other shading model (phong brings Whitted's integrator); returns what the overlay says. */
    public String toggleShading() {
        String note = seen.toggleShading();
        invalidate();
        return note;
    }

    /** I: the other integrator (the path integrator brings cook-torrance); returns what the overlay says. */
    public String toggleTransport() {
        String note = seen.toggleTransport();
        invalidate();
        return note;
    }

    /** + (+1) or - (-1): the depth one step up or down within 1 to max_recursion; returns what the overlay says. */
    public String stepDepth(int step) {
        int before = seen.depth();
        String note = seen.stepDepth(step);
        if (seen.depth() != before) {
            invalidate();
        }
        return note;
    }

    /**
     * The exposure keys: half a stop brighter (+1) or darker (-1); the frame on screen is encoded again, not
     * rendered again ({@link #takeRetoned}). Returns what the overlay says.
     */
    public String stepExposure(int step) {
        String note = seen.stepExposure(step);
        retoned = true;
        status.changed();
        return note;
    }

    /** T: the other tone curve; the frame on screen is encoded again. Returns what the overlay says. */
    public String toggleTone() {
        String note = seen.toggleTone();
        retoned = true;
        status.changed();
        return note;
    }

    /** Whether the view transform changed since this was last asked (the frame on screen is to be encoded again). */
    public boolean takeRetoned() {
        boolean was = retoned;
        retoned = false;
        return was;
    }

    /** F5 read the config again: its settings (under the scene's block) and flying speeds replace the user's. */
    public void configFile(Config config) {
        seen.configFile(config, scene);
        controller.setSpeeds(config.moveSpeed(), config.turnSpeed());
        controller.setFreeFlight(config.freeFlight());
        size.check(seen.config().limits());
        invalidate();
    }

    /**
     * The window's drawing area is now {@code width} x {@code height}: a new size gets its frame budget under
     * the settings' limits and the view is drawn anew; the same size changes nothing.
     */
    public void resized(int width, int height) {
        if (size.resize(width, height)) {
            size.check(seen.config().limits());
            invalidate();
        }
    }

    /** The camera moved or jumped (a motion, Home, a view, L): the view is drawn anew. */
    /**
     * Why a still of the view would not be what the headless command it prints gives (the scene file does not
     * load as it is on screen, or its render: block was left out, beyond the config's limits), or empty.
     */
    public String stillRefusal() {
        return status.error();
    }

    private void cameraMoved() {
        cameraNow = controller.camera();
        invalidate();
    }

    /** Something the frame depends on changed: compile again, draw a frame and refine it from the start. */
    private void invalidate() {
        compiled = null;
        needFrame = true;
        passesDone = 0;
        status.changed();
    }

    /** The scene compiled with the settings now, seen from the camera now. */
    public RenderScene compiled() {
        if (compiled == null) {
            compiled = compiledScenes.of(scene, seen.render(), controller.camera());
        }
        return compiled;
    }

    /** Whether a moving frame is still to be drawn since the view last changed. */
    public boolean needFrame() {
        return needFrame;
    }

    /** Still passes accumulated in the frame on screen. */
    public int passesDone() {
        return passesDone;
    }

    /** A moving frame is on screen: the refinement starts from nothing when the camera stops. */
    public void movingFrameShown() {
        needFrame = false;
        passesDone = 0;
    }

    /** {@code count} more still passes are on screen. */
    public void passesShown(int count) {
        needFrame = false;
        passesDone += count;
    }

    /** A frame failed: a failed pass may have reached the average, so the refinement starts over. */
    public void frameFailed() {
        needFrame = true;
        passesDone = 0;
    }

    public Scene scene() {
        return scene;
    }

    public ViewSettings settings() {
        return seen;
    }

    /**
     * The camera's controller, to read (its speed, the fov note) and to give the orbit's pivot; its pose
     * changes through this class ({@link #fly}, {@link #goTo}, {@link #home}, {@link #level}, {@link #show}).
     */
    public CameraController controller() {
        return controller;
    }

    /** The camera now (any thread). */
    public Camera camera() {
        return cameraNow;
    }

    /** The scene on screen: the last one that loaded (any thread). */
    public Scene sceneNow() {
        return sceneNow;
    }
}
