package glint.ui.view;

import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.scene.Camera;
import glint.scene.Scene;

/**
 * The window's render data: a scene is compiled once for its settings, and a camera move only swaps the
 * camera of the compiled scene ({@link RenderScene#withCamera}), so flying never rebuilds arrays or the
 * hierarchy.
 */
final class CompiledScenes {

    private RenderScene base; // the last scene and settings compiled, from any camera
    private Scene baseScene;

    /** The scene compiled with these settings, seen from {@code camera}. */
    RenderScene of(Scene scene, RenderSettings settings, Camera camera) {
        if (base == null || baseScene != scene || !settings.equals(base.settings())) {
            base = RenderScene.compile(scene, settings);
            baseScene = scene;
        }
        return base.withCamera(camera);
    }
}
