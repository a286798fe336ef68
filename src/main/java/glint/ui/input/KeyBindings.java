package glint.ui.input;

import glint.scenefile.SceneLoader;
import java.awt.event.KeyEvent;
import java.util.ArrayList;
import java.util.List;

/**
 * The one table of controls: which key does what. The window's key handling, the overlay's help
 * (key {@code ?}) and the controls table of docs/window.md all come from {@link #ALL}.
 */
public final class KeyBindings {

    /**
     * One row of the table.
     *
     * @param action   what it does
     * @param keys     how the key is written for people
     * @param meaning  what it does, for people
     * @param keyCodes AWT key codes that trigger it on key press (held actions: while pressed)
     * @param chars    typed characters that trigger it (for keys whose code depends on the layout)
     */
    public record Binding(Action action, String keys, String meaning, List<Integer> keyCodes, String chars) {

        public Binding {
            keyCodes = List.copyOf(keyCodes);
        }
    }

    public static final List<Binding> ALL = List.of(
            key(Action.FORWARD, "W", "fly forward", KeyEvent.VK_W),
            key(Action.BACK, "S", "fly back", KeyEvent.VK_S),
            key(Action.LEFT, "A", "fly left", KeyEvent.VK_A),
            key(Action.RIGHT, "D", "fly right", KeyEvent.VK_D),
            key(Action.UP, "R", "fly up (along the world's up; in free flight the camera's)", KeyEvent.VK_R),
            key(Action.DOWN, "F", "fly down (likewise)", KeyEvent.VK_F),
            key(Action.YAW_LEFT, "Left arrow", "turn left (yaw)", KeyEvent.VK_LEFT, KeyEvent.VK_KP_LEFT),
            key(Action.YAW_RIGHT, "Right arrow", "turn right (yaw)", KeyEvent.VK_RIGHT, KeyEvent.VK_KP_RIGHT),
            key(Action.PITCH_UP, "Up arrow", "look up (pitch)", KeyEvent.VK_UP, KeyEvent.VK_KP_UP),
            key(Action.PITCH_DOWN, "Down arrow", "look down (pitch)", KeyEvent.VK_DOWN, KeyEvent.VK_KP_DOWN),
            key(Action.ROLL_LEFT, "Q", "roll left", KeyEvent.VK_Q),
            key(Action.ROLL_RIGHT, "E", "roll right", KeyEvent.VK_E),
            key(Action.ZOOM_IN, "Z", "zoom in: narrow the field of view (to " + fmt(CameraController.MIN_FOV)
                    + " degree at least)", KeyEvent.VK_Z),
            key(Action.ZOOM_OUT, "X", "zoom out: widen the field of view (to " + fmt(CameraController.MAX_FOV)
                    + " degrees at most)", KeyEvent.VK_X),
            key(Action.FAST, "Shift", "held: fly " + fmt(CameraController.FAST_FACTOR) + "x faster",
                    KeyEvent.VK_SHIFT),
            pointer(Action.LOOK, "Mouse drag", "look around (drag right: turn right, drag up: look up)"),
            pointer(Action.ORBIT, "Ctrl + drag", "orbit round the point under the mouse (also: middle drag)"),
            pointer(Action.SPEED, "Mouse wheel", "flying speed: x" + fmt(CameraController.WHEEL_FACTOR)
                    + " a notch up, / " + fmt(CameraController.WHEEL_FACTOR) + " a notch down"),
            pointer(Action.FOCUS, "Click", "focus the lens on the point under the mouse (not on the sky)"),
            key(Action.TOGGLE_SHADING, "M or Tab", "switch shading: cook-torrance / phong",
                    KeyEvent.VK_M, KeyEvent.VK_TAB),
            key(Action.TOGGLE_INTEGRATOR, "I", "switch integrator: whitted / path / bdpt (light that bounces)",
                    KeyEvent.VK_I),
            typed(Action.DEPTH_UP, "+ (or =)", "recursion depth + 1", "+="),
            typed(Action.DEPTH_DOWN, "- (or _)", "recursion depth - 1", "-_"),
            typed(Action.EXPOSURE_UP, ". (or >)", "exposure + 1/2 stop: brighter", ".>"),
            typed(Action.EXPOSURE_DOWN, ", (or <)", "exposure - 1/2 stop: darker", ",<"),
            key(Action.TOGGLE_TONE, "T", "switch tone curve: neutral / standard (clamped at white)",
                    KeyEvent.VK_T),
            typed(Action.APERTURE_WIDER, "]", "widen the aperture: a pinhole to 1/"
                    + fmt(1 / CameraController.FIRST_APERTURE) + " of the focus, x"
                    + String.format(java.util.Locale.ROOT, "%.2f", CameraController.APERTURE_STEP), "]"),
            typed(Action.APERTURE_NARROWER, "[", "narrow the aperture; the narrowest, 0, is a pinhole", "["),
            key(Action.SCREENSHOT, "F12 or P", "save the view as a PNG: glint-YYYYMMDD-HHMMSS-mmm.png",
                    KeyEvent.VK_F12, KeyEvent.VK_P),
            key(Action.LEVEL, "L", "level the camera: take the roll out", KeyEvent.VK_L),
            key(Action.HOME, "Home", "back to the scene's camera", KeyEvent.VK_HOME),
            key(Action.VIEW, "1 to 9", "go to the scene's views (views: in the scene file)",
                    KeyEvent.VK_1, KeyEvent.VK_2, KeyEvent.VK_3, KeyEvent.VK_4, KeyEvent.VK_5, KeyEvent.VK_6,
                    KeyEvent.VK_7, KeyEvent.VK_8, KeyEvent.VK_9, KeyEvent.VK_NUMPAD1, KeyEvent.VK_NUMPAD2,
                    KeyEvent.VK_NUMPAD3, KeyEvent.VK_NUMPAD4, KeyEvent.VK_NUMPAD5, KeyEvent.VK_NUMPAD6,
                    KeyEvent.VK_NUMPAD7, KeyEvent.VK_NUMPAD8, KeyEvent.VK_NUMPAD9),
            key(Action.PRINT_CAMERA, "C", "print the camera as a scene's camera: block and a views: item",
                    KeyEvent.VK_C),
            key(Action.RENDER_STILL, "Enter", "render the view as a still PNG; Enter again or Esc cancels",
                    KeyEvent.VK_ENTER),
            pointer(Action.RENDER_STILL_PFM, "Shift + Enter", "the same, with a linear PFM beside the PNG"),
            pointer(Action.CANCEL_STILL, "Enter / Esc", "a still under way: cancel it at once; Esc does not quit"),
            key(Action.NEXT_SCENE, "Page Down", "open the next scene of the scene's folder", KeyEvent.VK_PAGE_DOWN),
            key(Action.PREVIOUS_SCENE, "Page Up", "open the previous scene of the scene's folder",
                    KeyEvent.VK_PAGE_UP),
            key(Action.RELOAD, "F5", "reload the scene and the config", KeyEvent.VK_F5),
            key(Action.TOGGLE_OVERLAY, "H", "show / hide the overlay", KeyEvent.VK_H),
            typed(Action.TOGGLE_HELP, "?", "show / hide this help", "?"),
            key(Action.QUIT, "Esc", "quit (while a still renders: cancel it)", KeyEvent.VK_ESCAPE));

    private KeyBindings() {
    }

    /** The action a pressed key code triggers, or null. */
    public static Action forKeyCode(int keyCode) {
        for (Binding b : ALL) {
            if (b.keyCodes().contains(keyCode)) {
                return b.action();
            }
        }
        return null;
    }

    /**
     * Which view (0 to 8) a key code of the {@link Action#VIEW} row goes to: keys 1 to 9, on the main
     * keyboard or the keypad; -1 for any other key.
     */
    public static int viewOf(int keyCode) {
        int i = of(Action.VIEW).keyCodes().indexOf(keyCode);
        return i < 0 ? -1 : i % SceneLoader.MAX_VIEWS;
    }

    /** The action a typed character triggers, or null. */
    public static Action forChar(char c) {
        for (Binding b : ALL) {
            if (b.chars().indexOf(c) >= 0) {
                return b.action();
            }
        }
        return null;
    }

    /** The row of an action. */
    public static Binding of(Action action) {
        for (Binding b : ALL) {
            if (b.action() == action) {
                return b;
            }
        }
        throw new IllegalArgumentException("no binding for " + action);
    }

    /** The help the overlay shows: one line a binding. */
    public static List<String> helpLines() {
        int width = 0;
        for (Binding b : ALL) {
            width = Math.max(width, b.keys().length());
        }
        List<String> lines = new ArrayList<>();
        for (Binding b : ALL) {
            lines.add(String.format("%-" + width + "s  %s", b.keys(), b.meaning()));
        }
        return lines;
    }

    /** The controls as a Markdown table (docs/window.md holds a copy; a test keeps them equal). */
    public static String markdownTable() {
        StringBuilder sb = new StringBuilder("| key | what it does |\n|---|---|\n");
        for (Binding b : ALL) {
            sb.append("| ").append(b.keys().replace("|", "\\|")).append(" | ")
                    .append(b.meaning().replace("|", "\\|")).append(" |\n");
        }
        return sb.toString();
    }

    private static Binding key(Action action, String keys, String meaning, Integer... codes) {
        return new Binding(action, keys, meaning, List.of(codes), "");
    }

    private static Binding typed(Action action, String keys, String meaning, String chars) {
        return new Binding(action, keys, meaning, List.of(), chars);
    }

    private static Binding pointer(Action action, String keys, String meaning) {
        return new Binding(action, keys, meaning, List.of(), "");
    }

    private static String fmt(double x) {
        return x == Math.rint(x) ? Long.toString((long) x) : Double.toString(x);
    }
}
