package glint.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Shading;
import glint.input.InputException;
import glint.scene.Scene;
import glint.scene.SceneLimits;
import glint.scene.SceneLoader;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Tracing a row's camera rays in stages (all hits, then all surfaces, then the shading, matte hits
 * lit together) gives the image of tracing them ray by ray bit for bit, and casts the same rays.
 */
class RowStagesTest {

    @ParameterizedTest
    @ValueSource(ints = {1, 4, 9})
    void theDefaultSceneAtAnySampleCount(int samples) throws IOException, InputException {
        assertSameImage(load("scenes/default.yaml"), 161, 120, samples, Shading.COOK_TORRANCE);
    }

    @Test
    void scenesWithAHierarchy() throws IOException, InputException {
        assertSameImage(load("scenes/bench/glass-25.yaml"), 120, 90, 1, Shading.COOK_TORRANCE);
        assertSameImage(load("scenes/bench/field-1000.yaml"), 120, 90, 4, Shading.COOK_TORRANCE);
    }

    @Test
    void randomScenesWithSeveralLightsOfBothKinds() {
        Random random = new Random(20261123);
        for (int scene = 0; scene < 24; scene++) {
            assertSameImage(Renders.scene(RandomScenes.upToSixSpheres(random)), 67, 50, scene % 3 == 0 ? 4 : 1,
                    Shading.COOK_TORRANCE);
        }
    }

    @Test
    void anEyeInsideASphereAndAnEyeBelowTheFloor() {
        String objects = """
                lights: [{type: point, position: [0, 3, 0], color: [1, 1, 1], intensity: 30}]
                objects:
                  - {type: sphere, center: [0, 1, 0], radius: 6, material: {type: matte, color: [0.7, 0.7, 0.7]}}
                  - {type: sphere, center: [1, 1, 2], radius: 0.7, material: {type: glass, ior: 1.5}}
                  - {type: sphere, center: [-1, 1, 2], radius: 0.5, material: {type: metal, color: [0.9, 0.9, 0.9]}}
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.5, 0.4, 0.3]}}
                """;
        assertSameImage(Renders.scene("camera: {position: [0, 1.5, -3], look_at: [1, 0.5, 2], fov: 70}\n" + objects),
                80, 60, 1, Shading.COOK_TORRANCE);
        assertSameImage(Renders.scene("camera: {position: [0, -1, -3], look_at: [0, 1, 2], fov: 70}\n" + objects),
                80, 60, 1, Shading.COOK_TORRANCE);
    }

    /**
     * The stage finds camera-ray hits sphere by sphere, over the pixels each sphere's screen range
     * spans: spheres smaller than a pixel, spheres cut by tile edges, spheres reaching behind the
     * eye (an unbounded range) and rows of up to 40 spheres, in odd image sizes and tilings.
     */
    @Test
    void tinySpheresSpheresCutByTilesAndSpheresBehindTheEye() {
        Random random = new Random(1122);
        for (int scene = 0; scene < 8; scene++) {
            StringBuilder yaml = new StringBuilder("""
                    camera: {position: [0, 1, -6], look_at: [0, 1, 0], fov: 60}
                    lights: [{type: point, position: [-3, 6, -4], color: [1, 1, 1], intensity: 60}]
                    objects:
                      - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.6, 0.6, 0.6]}}
                      - {type: sphere, center: [2, 1, -6.5], radius: 1.5, material: {type: matte, color: [0.2, 0.6, 0.2]}}
                    """);
            for (int i = 0, n = 5 + random.nextInt(36); i < n; i++) {
                double radius = random.nextInt(3) == 0 ? 0.002 + 0.01 * random.nextDouble() : 0.05 + 0.5 * random.nextDouble();
                yaml.append(String.format(java.util.Locale.ROOT,
                        "  - {type: sphere, center: [%.4f, %.4f, %.4f], radius: %.4f, material: {type: %s}}%n",
                        -4 + 8 * random.nextDouble(), 3 * random.nextDouble(), -2 + 6 * random.nextDouble(), radius,
                        random.nextBoolean() ? "matte, color: [0.8, 0.3, 0.2]" : "metal, color: [0.9, 0.9, 0.9]"));
            }
            assertSameImage(Renders.scene(yaml.toString()), 61 + scene, 47 + 2 * scene, scene % 2 == 0 ? 1 : 4,
                    Shading.COOK_TORRANCE);
        }
    }

    @Test
    void noLightsAndNothingButSky() {
        assertSameImage(Renders.scene("""
                objects:
                  - {type: sphere, center: [0, 1, 0], radius: 1, material: {type: matte, color: [0.7, 0.7, 0.7]}}
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: metal, color: [0.9, 0.9, 0.9]}}
                """), 64, 48, 1, Shading.COOK_TORRANCE);
        assertSameImage(Renders.scene("background: [0.1, 0.2, 0.3]\n"), 32, 24, 4, Shading.COOK_TORRANCE);
    }

    @Test
    void phongRowsAreTracedRayByRayInEitherTracer() throws IOException, InputException {
        assertSameImage(load("scenes/default.yaml"), 80, 60, 1, Shading.PHONG);
    }

    private static Scene load(String file) throws IOException, InputException {
        return SceneLoader.load(Path.of(file), SceneLimits.DEFAULT);
    }

    /** Renders the scene with rows in stages and ray by ray; compares every pixel and the rays cast. */
    private static void assertSameImage(Scene scene, int width, int height, int samples, Shading shading) {
        RenderSettings settings = new RenderSettings(shading, 5, 1e-3, Renders.EPSILON);
        FrameBuffer byRays = new FrameBuffer(width, height);
        FrameBuffer inStages = new FrameBuffer(width, height);
        long raysOneByOne, raysInStages;
        try (Tracer tracer = new Tracer(2, false)) {
            tracer.render(RenderScene.compile(scene, settings), byRays, samples, 0, 3);
            raysOneByOne = tracer.raysCast();
        }
        try (Tracer tracer = new Tracer(2, true)) {
            tracer.render(RenderScene.compile(scene, settings), inStages, samples, 0, 3);
            raysInStages = tracer.raysCast();
        }
        assertArrayEquals(byRays.rgb(), inStages.rgb());
        assertEquals(raysOneByOne, raysInStages, "rays cast");
        assertTrue(raysInStages >= (long) width * height * samples, "every camera ray is counted");
    }
}
