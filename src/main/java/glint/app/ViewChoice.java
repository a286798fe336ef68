package glint.app;

import glint.input.InputException;
import glint.input.Suggestions;
import glint.scene.Scene;
import glint.scene.View;
import java.util.ArrayList;
import java.util.List;

/**
 * Which camera a headless run sees the scene from ({@code --view}, README.md, "Using it"): its own
 * camera, its view N (counted from 1, as keys 1 to 9 of the window) or the view of a name. A whole
 * number is a view's number, anything else a name.
 */
final class ViewChoice {

    /** No --view: the scene's camera. */
    static final ViewChoice CAMERA = new ViewChoice(null);

    private final String given;

    private ViewChoice(String given) {
        this.given = given;
    }

    /** The choice {@code --view} gave, or {@link #CAMERA} for null. */
    static ViewChoice of(String given) {
        return given == null ? CAMERA : new ViewChoice(given);
    }

    /** Whether the scene is seen from a view rather than its camera. */
    boolean isView() {
        return given != null;
    }

    /**
     * The scene with the chosen view as its camera; an error when the scene has no such view, which
     * lists the views there are (or suggests the closest name).
     *
     * @param file the scene file, named in the message
     */
    Scene apply(Scene scene, String file) throws InputException {
        if (given == null) {
            return scene;
        }
        return scene.withCamera(view(scene.views(), file).camera());
    }

    /** {@code view 2 'from above'}: the chosen view, for a report line; empty for the scene's camera. */
    String describe(Scene scene) {
        int i = given == null ? -1 : indexIn(scene.views());
        // scene text, printed on standard output: escaped, so a line break or a terminal's escape shows as written
        return i < 0 ? "" : InputException.printable("view " + (i + 1) + " " + InputException.quote(scene.views().get(i).name()));
    }

    /** Where the chosen view is in {@code views}: by its number, or else by its name; -1 when it is not there. */
    private int indexIn(List<View> views) {
        if (isNumber()) {
            long n = given.length() > 9 ? Long.MAX_VALUE : Long.parseLong(given);
            return n >= 1 && n <= views.size() ? (int) n - 1 : -1;
        }
        for (int i = 0; i < views.size(); i++) {
            if (views.get(i).name().equals(given)) {
                return i;
            }
        }
        return -1;
    }

    private View view(List<View> views, String file) throws InputException {
        int i = indexIn(views);
        if (i >= 0) {
            return views.get(i);
        }
        String what = "--view " + (isNumber() ? given : InputException.quote(given)) + ": ";
        if (given.indexOf('\uFFFD') >= 0 && FileNames.asciiLocale()) { // café typed under LC_ALL=C: its bytes are lost
            throw new InputException("glint", 0, 0, what + "the name is not ASCII, and the locale (" + FileNames.locale()
                    + ") allows only ASCII arguments; " + FileNames.FIX);
        }
        if (views.isEmpty()) {
            throw new InputException("glint", 0, 0, what + InputException.quotePath(file)
                    + " has no views (a scene lists them under views:, docs/scene-format.md#views)");
        }
        if (isNumber()) {
            throw new InputException("glint", 0, 0, what + InputException.quotePath(file) + " has "
                    + count(views.size()) + ", from 1 to " + views.size() + ": " + listed(views));
        }
        List<String> names = views.stream().map(View::name).toList();
        String close = Suggestions.closest(given, names);
        throw new InputException("glint", 0, 0, what + InputException.quotePath(file) + " has no view of that name"
                + (close != null ? " (did you mean " + InputException.quote(close) + "?)" : "; its "
                + count(views.size()) + ": " + listed(views)));
    }

    private boolean isNumber() {
        return given.matches("[0-9]+");
    }

    private static String count(int n) {
        return n == 1 ? "1 view" : n + " views";
    }

    /** {@code 1 'the glass sphere', 2 'from above'} */
    private static String listed(List<View> views) {
        List<String> items = new ArrayList<>();
        for (int i = 0; i < views.size(); i++) {
            items.add((i + 1) + " " + InputException.quote(views.get(i).name()));
        }
        return String.join(", ", items);
    }
}
