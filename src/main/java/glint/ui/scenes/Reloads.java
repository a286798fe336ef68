package glint.ui.scenes;

import glint.config.Config;
import glint.input.InputException;
import glint.scene.Scene;
import glint.ui.view.SceneView;
import glint.ui.view.StatusLine;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;

/**
 * Reading the scene and config files again: F5 reads both, and the scene watcher hands over each saved
 * version of the scene file, loaded or not, which the engine takes at its next turn. The watcher's thread
 * only {@link #loaded} and {@link #failed}; everything else runs on the engine thread.
 */
public final class Reloads implements SceneWatcher.Listener {

    /** A version of the scene file the watcher read, waiting for the engine thread. */
    sealed interface Change permits Loaded, Failed {
    }

    /** It loaded. */
    record Loaded(Path file, Scene scene) implements Change {
    }

    /** It did not load, and why. */
    record Failed(Path file, InputException problem) implements Change {
    }

    private final SceneSource source;
    private final SceneView view;
    private final StatusLine status;
    private final Consumer<Config> configure;
    private final Runnable wake;
    private final AtomicReference<Change> pending = new AtomicReference<>(); // the watcher's latest, or null

    /**
     * @param configure applies a config read again (engine thread)
     * @param wake      wakes the engine thread when the watcher hands over a change
     */
    public Reloads(SceneSource source, SceneView view, StatusLine status, Consumer<Config> configure, Runnable wake) {
        this.source = source;
        this.view = view;
        this.status = status;
        this.configure = configure;
        this.wake = wake;
    }

    /** A version of the file shown now loaded. */
    @Override
    public void loaded(Scene newScene) {
        loaded(source.scenePath(), newScene);
    }

    /** A version of the file shown now does not load. */
    @Override
    public void failed(InputException problem) {
        failed(source.scenePath(), problem);
    }

    @Override
    public void loaded(Path file, Scene newScene) {
        pending.set(new Loaded(file, newScene));
        wake.run();
    }

    @Override
    public void failed(Path file, InputException problem) {
        pending.set(new Failed(file, problem));
        wake.run();
    }

    /**
     * Shows the change the watcher handed over since the last call, if any, unless it is of a file the window
     * no longer shows (a load that ended after Page Down).
     */
    public void takePending() {
        Change change = pending.getAndSet(null);
        if (change != null && !fileOf(change).equals(source.scenePath())) {
            return;
        }
        if (change instanceof Loaded loaded) {
            view.show(loaded.scene(), false);
            status.note("reloaded " + source.scenePath());
        } else if (change instanceof Failed failed) {
            status.error(failed.problem().getMessage());
        }
    }

    private static Path fileOf(Change change) {
        return change instanceof Loaded loaded ? loaded.file() : ((Failed) change).file();
    }

    /** Drops a change the watcher saw in a file the window no longer shows (another scene was opened). */
    void discardPending() {
        pending.set(null);
    }

    /** F5: the config and the scene again; the camera goes back to the scene's. */
    public void reload() {
        String problem = "";
        try {
            configure.accept(source.loadConfig());
        } catch (InputException e) {
            problem = e.getMessage();
        }
        try {
            view.show(source.loadScene(), true);
        } catch (InputException e) {
            problem = problem.isEmpty() ? e.getMessage() : problem;
        }
        if (!problem.isEmpty()) { // else the scene's, which may be a render: block beyond the limits
            status.error(problem);
        }
        status.note(problem.isEmpty() ? "reloaded " + source.scenePath() : "reload failed");
    }
}
