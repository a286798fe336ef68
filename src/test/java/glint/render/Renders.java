package glint.render;

import glint.config.Shading;
import glint.image.FrameBuffer;
import glint.input.InputException;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;

/** Test helper: parse a scene text and render it. */
public final class Renders {

    static final double EPSILON = 1e-9;

    private Renders() {
    }

    static Scene scene(String yaml) {
        try {
            return SceneLoader.parse("test.yaml", yaml);
        } catch (InputException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    static FrameBuffer render(String yaml, int width, int height, int samples, int depth, Shading shading) {
        return render(scene(yaml), width, height, samples, depth, shading, 2, 4);
    }

    static FrameBuffer render(Scene scene, int width, int height, int samples, int depth, Shading shading,
                              int threads, int divider) {
        RenderScene compiled = RenderScene.compile(scene, new RenderSettings(shading, depth, 0, EPSILON));
        FrameBuffer frame = new FrameBuffer(width, height);
        try (Tracer tracer = new Tracer(threads)) {
            tracer.render(compiled, frame, samples, 0, divider);
        }
        return frame;
    }

    /** Renders the compiled scene into {@code target} with a new 2-thread tracer, in 3 x 3 tiles; returns the rays cast. */
    static long renderCountingRays(RenderScene compiled, FrameBuffer target, int samples) {
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(compiled, target, samples, 0, 3);
            return tracer.raysCast();
        }
    }

    /**
     * The unit direction of the camera ray through the centre of pixel (x, y) for a camera at the
     * origin looking along +z with up +y, computed from the definition: the image plane at z = 1
     * spans x in [-tan(fov/2), tan(fov/2)], +x to the right, +y up.
     */
    public static double[] axisCameraRay(double fovDegrees, int width, int height, int x, int y) {
        double half = Math.tan(Math.toRadians(fovDegrees) / 2);
        double sx = ((x + 0.5) / width * 2 - 1) * half;
        double sy = (1 - (y + 0.5) / height * 2) * half * height / width;
        double len = Math.sqrt(sx * sx + sy * sy + 1);
        return new double[] {sx / len, sy / len, 1 / len};
    }
}
