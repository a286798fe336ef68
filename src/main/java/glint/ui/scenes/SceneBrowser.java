package glint.ui.scenes;

import glint.input.InputException;
import glint.ui.view.SceneView;
import glint.ui.view.StatusLine;
import java.nio.file.Path;

/**
 * Page Down (+1) and Page Up (-1): the next or previous scene file (.yaml, .yml) of the current scene's
 * folder, by name, round to the first or last ({@link SceneFolder}). The window watches that file from now
 * on; one that does not load says why and leaves the view as it was. Engine thread only.
 */
public final class SceneBrowser {

    private final SceneSource source;
    private final Reloads reloads;
    private final SceneView view;
    private final StatusLine status;

    public SceneBrowser(SceneSource source, Reloads reloads, SceneView view, StatusLine status) {
        this.source = source;
        this.reloads = reloads;
        this.view = view;
        this.status = status;
    }

    /** Opens the scene {@code step} files on in the folder (+1: the next, -1: the previous). */
    public void open(int step) {
        SceneFolder.Neighbour found = SceneFolder.neighbour(source.scenePath(), step);
        if (found.path() == null) {
            status.note(found.problem());
            return;
        }
        Path target = found.path();
        source.scenePath(target);
        reloads.discardPending(); // a change the watcher saw in the old file is no longer wanted
        try {
            view.show(source.loadScene(), true);
            status.note("opened " + target + " (" + found.number() + " of " + found.of() + ")");
        } catch (InputException e) {
            status.error(e.getMessage());
            status.note("opened " + target + ": it does not load");
        }
    }
}
