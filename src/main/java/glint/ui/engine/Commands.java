package glint.ui.engine;

import glint.scene.View;
import glint.ui.capture.CameraBlock;
import glint.ui.capture.Captures;
import glint.ui.input.Action;
import glint.ui.input.InputFrame;
import glint.ui.scenes.Reloads;
import glint.ui.scenes.SceneBrowser;
import glint.ui.view.SceneView;
import glint.ui.view.StatusLine;
import java.io.PrintWriter;
import java.util.List;

/**
 * What the command keys do (KeyBindings): each {@link Action} of kind command, once per press. The overlay
 * and help keys are the display's; the rest change the view, save it, or open and read files. Engine thread
 * only.
 */
final class Commands {

    private final SceneView view;
    private final StatusLine status;
    private final Captures captures;
    private final SceneBrowser browser;
    private final Reloads reloads;
    private final Runnable quit;
    private PrintWriter out = new PrintWriter(System.out, true); // key C's camera block, a still's report

    /** @param quit ends the engine's loop (Esc with no still under way) */
    Commands(SceneView view, StatusLine status, Captures captures, SceneBrowser browser, Reloads reloads,
             Runnable quit) {
        this.view = view;
        this.status = status;
        this.captures = captures;
        this.browser = browser;
        this.reloads = reloads;
        this.quit = quit;
    }

    /** Where key C prints the camera block and a still its report (standard output unless a test says otherwise). */
    void printTo(PrintWriter printer) {
        this.out = printer;
    }

    /** Does what {@code action} asks; {@code in} is the input it came with (which view a digit asks for). */
    public void run(Action action, InputFrame in) {
        switch (action) {
            case TOGGLE_SHADING -> status.note(view.toggleShading());
            case TOGGLE_INTEGRATOR -> status.note(view.toggleTransport());
            case DEPTH_UP -> status.note(view.stepDepth(1));
            case DEPTH_DOWN -> status.note(view.stepDepth(-1));
            case EXPOSURE_UP -> status.note(view.stepExposure(1));
            case EXPOSURE_DOWN -> status.note(view.stepExposure(-1));
            case TOGGLE_TONE -> status.note(view.toggleTone());
            case APERTURE_WIDER -> status.note(view.stepAperture(1));
            case APERTURE_NARROWER -> status.note(view.stepAperture(-1));
            case SCREENSHOT -> status.note(captures.screenshot());
            case RELOAD -> reloads.reload();
            case LEVEL -> {
                view.level();
                status.note("level");
            }
            case HOME -> {
                view.home();
                status.note("the scene's camera");
            }
            case VIEW -> goToView(in.view());
            case PRINT_CAMERA -> status.note(CameraBlock.print(view.camera(), view.settings().view(), out, status.log()));
            case NEXT_SCENE -> browser.open(1);
            case PREVIOUS_SCENE -> browser.open(-1);
            case RENDER_STILL, RENDER_STILL_PFM -> status.note(captures.still(action == Action.RENDER_STILL_PFM, out));
            case QUIT -> {
                if (captures.stillRunning()) { // Esc stops the still first; the next one quits
                    status.note(captures.cancelStill());
                } else {
                    quit.run();
                }
            }
            case CANCEL_STILL -> {
                if (captures.stillRunning()) { // else it ended before the key came: the overlay says how
                    status.note(captures.cancelStill());
                }
            }
            default -> {
                // overlay and help are the display's
            }
        }
    }

    /** Keys 1 to 9: the scene's views. */
    private void goToView(int index) {
        List<View> views = view.scene().views();
        if (index < 0 || index >= views.size()) {
            status.note(views.isEmpty() ? "the scene has no views (views: in the scene file)"
                    : "the scene has " + views.size() + (views.size() == 1 ? " view (key 1)"
                    : " views (keys 1 to " + views.size() + ")"));
            return;
        }
        view.goTo(views.get(index).camera());
        status.note("view " + (index + 1) + ": " + glint.input.InputException.printable(views.get(index).name()));
    }
}
