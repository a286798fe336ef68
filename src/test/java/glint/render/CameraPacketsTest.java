package glint.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
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
 * The SIMD path (camera rays in packets of four through the Vector API; the test JVM loads the
 * module) gives the plain path's image bit for bit and casts the same rays, wherever packets
 * stay together and wherever they must fall back to single rays.
 */
class CameraPacketsTest {

    @Test
    void theVectorApiIsLoadedForTheTests() {
        assertTrue(CameraPackets.available(), "surefire starts the test JVM with --add-modules jdk.incubator.vector");
        assertNotNull(CameraPackets.load());
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 4, 9})
    void theDefaultSceneIsTheSameAtAnySampleCount(int samples) throws IOException, InputException {
        Scene scene = SceneLoader.load(Path.of("scenes/default.yaml"), SceneLimits.DEFAULT);
        assertSameImage(scene, 161, 120, samples);
    }

    @Test
    void severalLightsOfBothKindsOverlappingSpheresAndTouchingOnes() {
        assertSameImage(Renders.scene("""
                camera: {position: [0, 2, -7], look_at: [0, 0.8, 0], fov: 55}
                lights:
                  - {type: point, position: [-4, 6, -5], color: [1, 0.9, 0.8], intensity: 80}
                  - {type: point, position: [3, 2, -1], color: [0.3, 0.4, 1], intensity: 20}
                  - {type: directional, direction: [0.3, -1, 0.4], color: [1, 1, 1], intensity: 0.7}
                objects:
                  - {type: sphere, center: [-1, 1, 0], radius: 1, material: {type: matte, color: [0.8, 0.2, 0.2]}}
                  - {type: sphere, center: [0.2, 1, 0.3], radius: 0.8, material: {type: matte, color: [0.2, 0.8, 0.2]}}
                  - {type: sphere, center: [2, 0.5, -1], radius: 0.5, material: {type: metal, color: [0.9, 0.9, 0.9], roughness: 0.2}}
                  - {type: sphere, center: [-2.5, 0.6, -1.5], radius: 0.6, material: {type: glass, ior: 1.5}}
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.6, 0.6, 0.6]}}
                  - {type: plane, point: [0, 0, 4], normal: [0, 0, -1], material: {type: matte, color: [0.3, 0.3, 0.5]}}
                """), 97, 64, 1);
    }

    @Test
    void anEyeInsideASphereOrBelowTheFloorMeetsSurfacesFromBehind() {
        String objects = """
                lights: [{type: point, position: [0, 3, 0], color: [1, 1, 1], intensity: 30}]
                objects:
                  - {type: sphere, center: [0, 1, 0], radius: 6, material: {type: matte, color: [0.7, 0.7, 0.7]}}
                  - {type: sphere, center: [1, 1, 2], radius: 0.7, material: {type: matte, color: [0.2, 0.3, 0.9]}}
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.5, 0.4, 0.3]}}
                """;
        assertSameImage(Renders.scene("camera: {position: [0, 1.5, -3], look_at: [1, 0.5, 2], fov: 70}\n" + objects),
                80, 60, 1);
        assertSameImage(Renders.scene("camera: {position: [0, -1, -3], look_at: [0, 1, 2], fov: 70}\n" + objects),
                80, 60, 1);
    }

    @Test
    void randomScenesOfUpToSixSpheres() {
        Random random = new Random(20261122);
        for (int scene = 0; scene < 24; scene++) {
            assertSameImage(Renders.scene(RandomScenes.upToSixSpheres(random)), 67, 50, scene % 3 == 0 ? 4 : 1);
        }
    }

    /** Renders the scene through both paths and compares every pixel and the ray counts. */
    private static void assertSameImage(Scene scene, int width, int height, int samples) {
        RenderSettings plain = new RenderSettings(Shading.COOK_TORRANCE, 5, 1e-3, Renders.EPSILON);
        FrameBuffer expected = new FrameBuffer(width, height);
        FrameBuffer actual = new FrameBuffer(width, height);
        long plainRays = Renders.renderCountingRays(RenderScene.compile(scene, plain), expected, samples);
        long packetRays = Renders.renderCountingRays(RenderScene.compile(scene, plain.withSimd(true)), actual, samples);
        assertArrayEquals(expected.rgb(), actual.rgb());
        assertEquals(plainRays, packetRays, "rays cast");
    }
}
