package glint.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;

import glint.image.FrameBuffer;
import glint.image.ImageWriter;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The same settings give the same bytes for any thread or tile count (docs/conventions.md, "Pixels and
 * samples").
 */
class DeterminismTest {

    @Test
    void identicalPngBytesForAnyThreadAndTileCount() throws Exception {
        Scene scene = SceneLoader.load(Path.of("scenes/bench/spec-example.yaml"));
        byte[] reference = png(Renders.render(scene, 96, 72, 4, 5, Shading.COOK_TORRANCE, 1, 1));
        for (int threads : new int[] {1, 2, 7}) {
            for (int divider : new int[] {1, 8, 13}) {
                byte[] bytes = png(Renders.render(scene, 96, 72, 4, 5, Shading.COOK_TORRANCE, threads, divider));
                assertArrayEquals(reference, bytes, threads + " threads, divider " + divider);
            }
        }
    }

    /** A sphere light, a sun with a size, a rough metal and glass: the lights' samples follow the pixel and sample. */
    private static final String LIGHTS_WITH_A_SIZE = """
            camera: {position: [0, 2, -4], look_at: [0, 0.5, 0.5], fov: 55}
            background: [0.2, 0.25, 0.3]
            lights:
              - {type: point, position: [1.2, 2.2, 0.4], radius: 0.4, intensity: 8}
              - {type: directional, direction: [-0.3, -1, 0.4], angle: 6, intensity: 1.5}
            objects:
              - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
              - {type: sphere, center: [-0.7, 0.5, 0.3], radius: 0.5, material: {type: glass}}
              - {type: sphere, center: [0.7, 0.5, 0.6], radius: 0.5, material: {type: metal, roughness: 0.3}}
            """;

    @ParameterizedTest
    @EnumSource(LightTransport.class)
    void lightsWithASizeGiveTheSameBytesForAnyThreadAndTileCount(LightTransport transport) throws Exception {
        RenderScene compiled = RenderScene.compile(Renders.scene(LIGHTS_WITH_A_SIZE),
                new RenderSettings(Shading.COOK_TORRANCE, 6, 0.01, 1e-9).withTransport(transport));
        byte[] reference = null;
        for (int threads : new int[] {1, 2, 7}) {
            for (int divider : new int[] {1, 8, 13}) {
                FrameBuffer frame = new FrameBuffer(64, 48);
                try (Tracer tracer = new Tracer(threads)) {
                    tracer.render(compiled, frame, 4, 1, divider);
                }
                byte[] bytes = png(frame);
                if (reference == null) {
                    reference = bytes;
                }
                assertArrayEquals(reference, bytes, transport + ", " + threads + " threads, divider " + divider);
            }
        }
    }

    @Test
    void aLensGivesTheSameBytesForAnyThreadAndTileCount() throws Exception {
        // a thin lens (aperture 0.1): each ray's lens point is a function of its pixel, frame and sample
        Scene scene = SceneLoader.load(Path.of("src/test/resources/reference-pt/lens.yaml"));
        for (LightTransport transport : LightTransport.values()) {
            RenderScene compiled = RenderScene.compile(scene,
                    new RenderSettings(Shading.COOK_TORRANCE, 5, 0.01, 1e-9).withTransport(transport));
            float[] reference = null;
            for (int threads : new int[] {1, 2, 7}) {
                for (int divider : new int[] {1, 8, 13}) {
                    FrameBuffer frame = new FrameBuffer(96, 72);
                    try (Tracer tracer = new Tracer(threads)) {
                        tracer.render(compiled, frame, 4, 2, divider);
                    }
                    if (reference == null) {
                        reference = frame.rgb().clone();
                    }
                    assertArrayEquals(reference, frame.rgb(), transport + ", " + threads + " threads, divider " + divider);
                }
            }
        }
    }

    @Test
    void rouletteDrawsDoNotDependOnThreadsOrTiles() throws Exception {
        // glass on a mirror pruned at 0.2: most reflections off glass and many refractions go by roulette
        Scene scene = SceneLoader.load(Path.of("src/test/resources/scenes/glass-on-mirror.yaml"));
        RenderScene compiled = RenderScene.compile(scene, new RenderSettings(Shading.COOK_TORRANCE, 12, 0.2, 1e-9));
        byte[] reference = null;
        for (int threads : new int[] {1, 2, 7}) {
            for (int divider : new int[] {1, 8, 13}) {
                FrameBuffer frame = new FrameBuffer(96, 72);
                try (Tracer tracer = new Tracer(threads)) {
                    tracer.render(compiled, frame, 4, 3, divider);
                }
                byte[] bytes = png(frame);
                if (reference == null) {
                    reference = bytes;
                }
                assertArrayEquals(reference, bytes, threads + " threads, divider " + divider);
            }
        }
    }

    @Test
    void progressivePassesAverageToTheStillImage() throws Exception {
        // pruned by roulette, whose draws follow the sample index: the passes refine to the still image
        Scene scene = SceneLoader.load(Path.of("src/test/resources/scenes/glass-on-mirror.yaml"));
        assertPassesAverageToTheStill(RenderScene.compile(scene, new RenderSettings(Shading.COOK_TORRANCE, 12, 0.05,
                1e-9)));
    }

    @ParameterizedTest
    @EnumSource(LightTransport.class)
    void passesOfLightsWithASizeAverageToTheStillImage(LightTransport transport) {
        // each pass is one of the still's stratified samples of the lights, so the passes refine to the still
        assertPassesAverageToTheStill(RenderScene.compile(Renders.scene(LIGHTS_WITH_A_SIZE),
                new RenderSettings(Shading.COOK_TORRANCE, 6, 0.01, 1e-9).withTransport(transport)));
    }

    private static void assertPassesAverageToTheStill(RenderScene compiled) {
        int samples = 9;
        FrameBuffer still = new FrameBuffer(40, 30);
        FrameBuffer pass = new FrameBuffer(40, 30);
        double[] sum = new double[still.rgb().length];
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(compiled, still, samples, 0, 4);
            for (int k = 0; k < samples; k++) {
                tracer.renderPass(compiled, pass, samples, k, 3);
                for (int i = 0; i < sum.length; i++) {
                    sum[i] += pass.rgb()[i];
                }
            }
        }
        for (int i = 0; i < sum.length; i++) {
            double expected = still.rgb()[i];
            org.junit.jupiter.api.Assertions.assertEquals(expected, sum[i] / samples, 1e-6 * Math.max(1, expected));
        }
    }

    @Test
    void swappingTheCameraRendersWhatCompilingWithThatCameraRenders() throws Exception {
        Scene scene = SceneLoader.load(Path.of("scenes/bench/field-1000.yaml"));
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, 5, 1e-3, 1e-9);
        glint.scene.Camera moved = glint.scene.Camera.lookAt(new glint.math.Vector3d(3, 2, -4),
                new glint.math.Vector3d(0, 0, 3), glint.math.Vector3d.UNIT_Y, 50);
        RenderScene swapped = RenderScene.compile(scene, settings).withCamera(moved);
        RenderScene fresh = RenderScene.compile(scene.withCamera(moved), settings);
        FrameBuffer a = new FrameBuffer(64, 48), b = new FrameBuffer(64, 48);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(swapped, a, 1, 0, 4);
            tracer.render(fresh, b, 1, 0, 4);
        }
        assertArrayEquals(b.rgb(), a.rgb());
    }

    private static byte[] png(FrameBuffer frame) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ImageIO.write(ImageWriter.toImage(frame), "png", out);
        return out.toByteArray();
    }
}
