package glint.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;

import glint.accel.FlatList;
import glint.image.FrameBuffer;
import glint.scene.Scene;
import org.junit.jupiter.api.Test;

/**
 * A wall 1e15 away lit by a light at the origin, with a small epsilon (a valid positive setting):
 * the shadow rays' ends, computed in doubles, land within the light cells' reach although the rays
 * themselves pass up to ~0.1 from the light, so a cell of the wrong direction answers them and the
 * sphere's shadow edge is lost. Brute force and the policy's aggregates must give the same pixels.
 */
class LightCellsFarSurfaceRenderTest {

    @Test
    void aFarWallShadowedNearTheLightRendersAsBruteForceDoes() {
        Scene scene = Renders.scene("""
                camera: {position: [0, 0, -1], look_at: [0, 0, 1], fov: 100}
                lights: [{type: point, position: [0, 0, 0], intensity: 1e30}]
                objects:
                  - {type: sphere, center: [0, 0, 1], radius: 0.5}
                  - {type: plane, point: [0, 0, 1e15], normal: [0, 0, 1]}
                """);
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, 1, 0, 1e-30);
        float[] brute = render(RenderScene.compile(scene, settings, FlatList::new));
        float[] chosen = render(RenderScene.compile(scene, settings));
        assertArrayEquals(brute, chosen);
    }

    private static float[] render(RenderScene compiled) {
        FrameBuffer frame = new FrameBuffer(320, 240);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(compiled, frame, 1, 0, 3);
        }
        return frame.rgb();
    }
}
