package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.bench.BenchScenes;
import glint.bench.PairedFrames;
import glint.config.Shading;
import glint.input.InputException;
import glint.scene.Scene;
import glint.scene.SceneLoader;
import java.nio.file.Path;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The yardstick and Glint render the same image: every ray of the plain tracer tests every surface
 * one after another, so where the two agree, Glint's culling, staged rows and chords inside glass
 * found what brute force finds, and where they disagree one of them is wrong.
 */
class PlainTracerTest {

    @ParameterizedTest
    @ValueSource(ints = {1, 2, 3, 5, 8})
    void theDefaultSceneAtEveryDepth(int depth) throws InputException {
        assertSameImage(SceneLoader.load(Path.of("scenes/default.yaml")), settings(depth, 0.01), 200, 150, 2);
    }

    @Test
    void theDefaultSceneWithNoPruning() throws InputException {
        assertSameImage(SceneLoader.load(Path.of("scenes/default.yaml")), settings(6, 0), 160, 120, 1);
    }

    @Test
    void scenesWithAHierarchy() throws InputException {
        assertSameImage(SceneLoader.parse("glass-25", BenchScenes.row(25, "glass")), settings(5, 0.01), 160, 120, 2);
        assertSameImage(SceneLoader.parse("field-200", BenchScenes.field(200)), settings(5, 0.01), 120, 90, 2);
    }

    @Test
    void randomScenesWithSeveralLightsOfBothKinds() {
        Random random = new Random(20261201);
        for (int scene = 0; scene < 24; scene++) {
            assertSameImage(Renders.scene(RandomScenes.upToSixSpheres(random)), settings(1 + scene % 6, 0.01), 64, 48,
                    1 + scene % 2);
        }
    }

    @Test
    void theComparisonTellsImagesApart() throws InputException {
        Scene scene = SceneLoader.load(Path.of("scenes/default.yaml"));
        FrameBuffer depthFive = render(RenderScene.compile(scene, settings(5, 0.01)), 80, 60);
        FrameBuffer depthTwo = renderPlain(RenderScene.compile(scene, settings(2, 0.01)), 80, 60, 1);
        assertTrue(PairedFrames.differingPixels(depthFive, depthTwo) > 100,
                "depth 2 against depth 5 differs wherever the glass sphere shows");
    }

    @Test
    void refusesWhatItDoesNotModel() throws InputException {
        Scene scene = SceneLoader.load(Path.of("scenes/default.yaml"));
        RenderScene phong = RenderScene.compile(scene, new RenderSettings(Shading.PHONG, 5, 0.01, Renders.EPSILON));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new PlainTracer(phong, 1));
        assertEquals("the plain tracer shades cook-torrance with the exact Fresnel equations, got PHONG with EXACT Fresnel",
                e.getMessage());
        RenderScene schlick = RenderScene.compile(scene,
                settings(5, 0.01).withGlassFresnel(RenderSettings.GlassFresnel.SCHLICK));
        assertThrows(IllegalArgumentException.class, () -> new PlainTracer(schlick, 1));
        RenderScene exact = RenderScene.compile(scene, settings(5, 0.01));
        assertThrows(IllegalArgumentException.class, () -> new PlainTracer(exact, 0));
    }

    private static RenderSettings settings(int depth, double minWeight) {
        return new RenderSettings(Shading.COOK_TORRANCE, depth, minWeight, Renders.EPSILON);
    }

    private static void assertSameImage(Scene scene, RenderSettings settings, int width, int height, int threads) {
        RenderScene compiled = RenderScene.compile(scene, settings);
        FrameBuffer glint = render(compiled, width, height);
        FrameBuffer plain = renderPlain(compiled, width, height, threads);
        assertEquals(0, PairedFrames.differingPixels(glint, plain),
                "pixels that differ by more than " + PairedFrames.TOLERANCE);
    }

    private static FrameBuffer render(RenderScene scene, int width, int height) {
        FrameBuffer frame = new FrameBuffer(width, height);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(scene, frame, 1, 0, 3);
        }
        return frame;
    }

    private static FrameBuffer renderPlain(RenderScene scene, int width, int height, int threads) {
        FrameBuffer frame = new FrameBuffer(width, height);
        try (PlainTracer plain = new PlainTracer(scene, threads)) {
            plain.render(frame);
        }
        return frame;
    }
}
