package glint.render;

import glint.image.FrameBuffer;
import glint.input.InputException;
import glint.math.Vector3d;
import glint.scene.Camera;
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
     * origin looking along +z with up +y: the renderer's own ray ({@link PinholeCamera}).
     */
    public static double[] axisCameraRay(double fovDegrees, int width, int height, int x, int y) {
        Vector3d d = new PinholeCamera(Camera.lookAt(Vector3d.ZERO, Vector3d.UNIT_Z, Vector3d.UNIT_Y, fovDegrees))
                .direction(x + 0.5, y + 0.5, width, height);
        return new double[] {d.x(), d.y(), d.z()};
    }
}
