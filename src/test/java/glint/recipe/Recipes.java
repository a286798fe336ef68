package glint.recipe;

import glint.image.FrameBuffer;
import glint.input.InputException;
import glint.registry.Registry;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Shading;
import glint.render.Tracer;
import glint.scene.Scene;
import glint.scenefile.SceneLimits;
import glint.scenefile.SceneLoader;

/** Test helper: a scene read and rendered through a registry with a type added by its recipe. */
final class Recipes {

    private Recipes() {
    }

    static Scene scene(Registry registry, String yaml) {
        try {
            return SceneLoader.parse("recipe.yaml", yaml, SceneLimits.DEFAULT, registry);
        } catch (InputException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    /** The error message a scene gives, which must be an error. */
    static String error(Registry registry, String yaml) {
        try {
            SceneLoader.parse("recipe.yaml", yaml, SceneLimits.DEFAULT, registry);
        } catch (InputException e) {
            return e.getMessage();
        }
        throw new AssertionError("expected an error for " + yaml);
    }

    /** One sample a pixel, recursion depth {@code depth}, two threads in 3 x 3 tiles. */
    static FrameBuffer render(Registry registry, String yaml, int width, int height, int depth) {
        RenderScene compiled = RenderScene.compile(scene(registry, yaml),
                new RenderSettings(Shading.COOK_TORRANCE, depth, 0, 1e-9), registry);
        FrameBuffer frame = new FrameBuffer(width, height);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(compiled, frame, 1, 0, 3);
        }
        return frame;
    }
}
