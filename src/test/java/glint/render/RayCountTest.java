package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;

import glint.image.FrameBuffer;
import org.junit.jupiter.api.Test;

/** The ray count behind rays_per_s counts every camera, secondary and shadow ray once. */
class RayCountTest {

    private static long raysFor(String yaml, int samples, int depth) {
        RenderScene scene = RenderScene.compile(Renders.scene(yaml), new RenderSettings(Shading.COOK_TORRANCE, depth, 0, 1e-9));
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(scene, new FrameBuffer(8, 6), samples, 0, 2);
            return tracer.raysCast();
        }
    }

    @Test
    void anEmptySceneCastsOneRayPerSample() {
        assertEquals(8 * 6 * 4, raysFor("background: [1, 1, 1]\n", 4, 5));
    }

    @Test
    void aLitFloorFillingTheViewAddsOneShadowRayPerSample() {
        String floor = """
                camera: {position: [0, 1, 0], look_at: [0, 0, 0.01], fov: 40}
                lights:
                  - {type: point, position: [0, 5, 0]}
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
                """;
        assertEquals(2 * 8 * 6, raysFor(floor, 1, 5));
    }

    @Test
    void aMirrorFloorAddsTheReflectedRayWhichEscapes() {
        String mirror = """
                camera: {position: [0, 1, 0], look_at: [0, 0, 0.01], fov: 40}
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: metal, color: [1, 1, 1]}}
                """;
        assertEquals(2 * 8 * 6, raysFor(mirror, 1, 5));
        assertEquals(8 * 6, raysFor(mirror, 1, 1), "depth 1 follows no reflection");
    }
}
