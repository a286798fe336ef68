package glint.ui.input;

/**
 * What a key (or the mouse) asks for. Motions act for as long as their key is held; commands act
 * once per press.
 */
public enum Action {
    FORWARD(Kind.MOTION), BACK(Kind.MOTION), LEFT(Kind.MOTION), RIGHT(Kind.MOTION),
    UP(Kind.MOTION), DOWN(Kind.MOTION),
    YAW_LEFT(Kind.MOTION), YAW_RIGHT(Kind.MOTION), PITCH_UP(Kind.MOTION), PITCH_DOWN(Kind.MOTION),
    ROLL_LEFT(Kind.MOTION), ROLL_RIGHT(Kind.MOTION),
    /** Narrow / widen the field of view while held. */
    ZOOM_IN(Kind.MOTION), ZOOM_OUT(Kind.MOTION),
    /** Held with motion keys: fly and turn faster. */
    FAST(Kind.MODIFIER),
    /** Not a key: dragging with the mouse looks around. */
    LOOK(Kind.POINTER),
    /** Not a key: dragging with Ctrl or the middle button orbits around the point under the mouse. */
    ORBIT(Kind.POINTER),
    /** Not a key: the mouse wheel changes the flying speed. */
    SPEED(Kind.POINTER),
    /** Not a key: a click (no drag, no Ctrl) focuses the lens on the point under the mouse. */
    FOCUS(Kind.POINTER),
    /** Widen / narrow the lens's aperture a step. */
    APERTURE_WIDER(Kind.COMMAND), APERTURE_NARROWER(Kind.COMMAND),
    TOGGLE_SHADING(Kind.COMMAND), TOGGLE_INTEGRATOR(Kind.COMMAND), DEPTH_UP(Kind.COMMAND), DEPTH_DOWN(Kind.COMMAND),
    /** Half a stop of exposure brighter / darker; the other tone curve. */
    EXPOSURE_UP(Kind.COMMAND), EXPOSURE_DOWN(Kind.COMMAND), TOGGLE_TONE(Kind.COMMAND),
    SCREENSHOT(Kind.COMMAND), RELOAD(Kind.COMMAND), QUIT(Kind.COMMAND),
    TOGGLE_OVERLAY(Kind.COMMAND), TOGGLE_HELP(Kind.COMMAND),
    /** Takes the roll out of the camera. */
    LEVEL(Kind.COMMAND),
    /** Back to the scene file's camera. */
    HOME(Kind.COMMAND),
    /** To one of the scene's views (which one: {@link InputFrame#view}). */
    VIEW(Kind.COMMAND),
    /** Prints the camera as a scene's camera block. */
    PRINT_CAMERA(Kind.COMMAND),
    NEXT_SCENE(Kind.COMMAND), PREVIOUS_SCENE(Kind.COMMAND),
    /** Renders the view as a still image in the background, or cancels that render. */
    RENDER_STILL(Kind.COMMAND),
    /** The same, writing a linear PFM beside the PNG (Shift with the render key). */
    RENDER_STILL_PFM(Kind.COMMAND),
    /**
     * Not a key of its own: the render key or Esc pressed while the overlay said a still was under way.
     * It cancels that still, and does nothing else if the still ended meanwhile (it never starts one, never quits).
     */
    CANCEL_STILL(Kind.COMMAND);

    /** How an action is triggered. */
    public enum Kind { MOTION, MODIFIER, POINTER, COMMAND }

    private final Kind kind;

    Action(Kind kind) {
        this.kind = kind;
    }

    public Kind kind() {
        return kind;
    }

    /** L, Home and the views put the camera somewhere: they act after the motion of the same interval. */
    public boolean jumpsCamera() {
        return this == LEVEL || this == HOME || this == VIEW;
    }

    public boolean isHeld() {
        return kind == Kind.MOTION || kind == Kind.MODIFIER;
    }
}
