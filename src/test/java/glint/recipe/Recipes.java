package glint.recipe;

import glint.config.Shading;
import glint.input.InputException;
import glint.render.FrameBuffer;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Tracer;
import glint.scene.Registry;
import glint.scene.Scene;
import glint.scene.SceneLimits;
import glint.scene.SceneLoader;

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

    /**
     * The unit direction of the camera ray through the centre of pixel (x, y) for a camera at the
     * origin looking along +z with up +y, from the definition: the image plane at z = 1 spans x in
     * [-tan(fov/2), tan(fov/2)], +x to the right, +y up.
     */
    static double[] cameraRay(double fovDegrees, int width, int height, int x, int y) {
        double half = Math.tan(Math.toRadians(fovDegrees) / 2);
        double sx = ((x + 0.5) / width * 2 - 1) * half;
        double sy = (1 - (y + 0.5) / height * 2) * half * height / width;
        double len = Math.sqrt(sx * sx + sy * sy + 1);
        return new double[] {sx / len, sy / len, 1 / len};
    }
}
