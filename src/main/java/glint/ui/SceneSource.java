package glint.ui;

import glint.config.Config;
import glint.input.InputException;
import glint.scene.Scene;
import glint.scene.SceneLoader;
import java.nio.file.Path;

/** Where the window's scene and config come from, to read them again on F5 or when the file changes. */
public final class SceneSource {

    private final Path scenePath;
    private final ConfigSource configSource;

    public SceneSource(Path scenePath, ConfigSource configSource) {
        this.scenePath = scenePath;
        this.configSource = configSource;
    }

    public Path scenePath() {
        return scenePath;
    }

    public Scene loadScene() throws InputException {
        return SceneLoader.load(scenePath);
    }

    public Config loadConfig() throws InputException {
        return configSource.load();
    }
}
