package glint.recipe;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import glint.math.Vector3d;
import glint.registry.Registry;
import glint.render.CameraModel;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Shading;
import glint.render.Tracer;
import glint.scene.Scene;
import org.junit.jupiter.api.Test;

/**
 * The camera recipe of docs/architecture.md: a camera model of its own ({@link OrthographicCamera}, one
 * file in the test sources) renders through the product's tracer, both integrators' rows searched ray by
 * ray from its own origins, and shows what an orthographic view shows: a ball is a disc of its own
 * radius across the window at any distance.
 */
class CameraRecipeTest {

    private static final int SIZE = 40;
    /** The window is 4 units across, 10 pixels a unit. */
    private static final double SPAN = 4;

    @Test
    void aBallIsADiscOfItsRadiusWhateverItsDistance() {
        for (double distance : new double[] {3, 30, 300}) {
            FrameBuffer frame = render("""
                    camera: {position: [0, 0, 0], look_at: [0, 0, 1]}
                    background: [0, 0, 1]
                    lights:
                      - {type: directional, direction: [0, 0, 1], intensity: 1}
                    objects:
                      - {type: sphere, center: [0.5, 0, DISTANCE], radius: 1, material: {type: matte, color: [1, 0, 0]}}
                    """.replace("DISTANCE", Double.toString(distance)));
            for (int y = 0; y < SIZE; y++) {
                for (int x = 0; x < SIZE; x++) {
                    // the pixel's centre across the window, scene units from the ball's axis
                    double wx = (x + 0.5) / SIZE * SPAN - SPAN / 2 - 0.5, wy = SPAN / 2 - (y + 0.5) / SIZE * SPAN;
                    double r = Math.hypot(wx, wy);
                    if (r < 0.97) {
                        assertTrue(frame.get(x, y, 0) > 0 && frame.get(x, y, 2) == 0, "ball at " + x + ", " + y);
                    } else if (r > 1.03) {
                        assertEquals(1, frame.get(x, y, 2), "sky at " + x + ", " + y + ", distance " + distance);
                    }
                }
            }
        }
    }

    @Test
    void aRaysPointMapsBackToItsFilmPoint() {
        Scene scene = Recipes.scene(Registry.STANDARD, "camera: {position: [1, 2, 3], look_at: [4, 0, 7]}");
        CameraModel camera = OrthographicCamera.of(scene.camera(), SPAN);
        double[] ox = new double[1], oy = new double[1], oz = new double[1];
        double[] dx = new double[1], dy = new double[1], dz = new double[1];
        for (double px = 0.5; px < SIZE; px += 3.7) {
            for (double py = 0.25; py < SIZE; py += 5.1) {
                camera.ray(px, py, 0.3, 0.8, SIZE, SIZE, ox, oy, oz, dx, dy, dz, 0);
                Vector3d along = new Vector3d(ox[0] + 7 * dx[0], oy[0] + 7 * dy[0], oz[0] + 7 * dz[0]);
                CameraModel.ImagePoint back = camera.imagePoint(along, SIZE, SIZE).orElseThrow();
                assertEquals(px, back.px(), 1e-9);
                assertEquals(py, back.py(), 1e-9);
            }
        }
    }

    private static FrameBuffer render(String yaml) {
        Scene scene = Recipes.scene(Registry.STANDARD, yaml);
        RenderScene compiled = RenderScene.compile(scene, new RenderSettings(Shading.COOK_TORRANCE, 2, 0, 1e-9))
                .withCamera(OrthographicCamera.of(scene.camera(), SPAN));
        FrameBuffer frame = new FrameBuffer(SIZE, SIZE);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(compiled, frame, 1, 0, 3);
        }
        return frame;
    }
}
