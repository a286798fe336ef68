package glint.ui.scenes;

import glint.config.Config;
import glint.config.Flags;
import glint.input.InputException;
import glint.scene.Scene;
import glint.scenefile.SceneLimits;
import glint.scenefile.SceneLoader;
import java.nio.file.Path;

/**
 * Where the window's scene and config come from, to read them again on F5 or when the file changes, or to
 * read the next scene of the folder (Page Down). The
 * scene is read within the config's scene limits ({@code max_scene_bytes}, {@code max_objects},
 * {@code max_lights}); the window sets them from its config at start and again after F5.
 */
public final class SceneSource {

    private volatile Path scenePath;
    private final ConfigSource configSource;
    private volatile SceneLimits limits = SceneLimits.DEFAULT;
    private final Flags flags;
    private final Path configFile;
    private volatile Loaded lastLoaded;

    public SceneSource(Path scenePath, ConfigSource configSource) {
        this(scenePath, configSource, Flags.NONE);
    }

    /** A source whose scenes are seen with the command line's {@code flags} above their render: blocks. */
    public SceneSource(Path scenePath, ConfigSource configSource, Flags flags) {
        this(scenePath, configSource, flags, null);
    }

    /** A source whose config is read from {@code configFile} (null: none, the defaults). */
    public SceneSource(Path scenePath, ConfigSource configSource, Flags flags, Path configFile) {
        this.scenePath = scenePath;
        this.configSource = configSource;
        this.flags = flags;
        this.configFile = configFile;
    }

    /** The config file the window reads, for the headless command of a still; null when it runs on the defaults. */
    public Path configFile() {
        return configFile;
    }

    /** The command line's settings, which rank above a scene's render: block. */
    public Flags flags() {
        return flags;
    }

    public Path scenePath() {
        return scenePath;
    }

    /** Reads and watches another scene file from now on (Page Down, Page Up; any thread). */
    public void scenePath(Path newScene) {
        this.scenePath = newScene;
    }

    /** The limits the scene is read within. */
    public SceneLimits limits() {
        return limits;
    }

    /** Reads the scene within these limits from now on (any thread). */
    public void limits(SceneLimits sceneLimits) {
        this.limits = sceneLimits;
    }

    public Scene loadScene() throws InputException {
        return loadScene(scenePath);
    }

    /** Reads {@code file} as the window's scene, within these limits; remembers its text if it is the window's file. */
    public Scene loadScene(Path file) throws InputException {
        String text = SceneLoader.read(file, limits);
        Scene scene = SceneLoader.parse(file.toString(), text, limits);
        if (file.equals(scenePath)) { // not a load of a file the window left (Page Down) that ended late
            lastLoaded = new Loaded(file, scene, text);
        }
        return scene;
    }

    /**
     * Why the scene file on disk is not the scene {@code shown} (a save that loads but is not on screen yet,
     * or one that no longer loads), in words for the still it refuses; empty when it is the same text.
     */
    public String changedSince(Scene shown) {
        Loaded last = lastLoaded;
        if (last == null) { // nothing was loaded here: nothing to compare
            return "";
        }
        String changed = InputException.quotePath(scenePath) + " changed on disk since it was shown; the new version"
                + " is shown within a second (or its error), then Enter renders it";
        if (last.scene() != shown || !last.file().equals(scenePath)) {
            return changed;
        }
        try {
            return SceneLoader.read(scenePath, limits).equals(last.text()) ? "" : changed;
        } catch (InputException e) {
            return e.getMessage();
        }
    }

    /** The last scene loaded from the window's file, and the text it was read from. */
    private record Loaded(Path file, Scene scene, String text) {
    }

    public Config loadConfig() throws InputException {
        return configSource.load();
    }
}
