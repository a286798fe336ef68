package glint.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Shading;
import glint.geometry.AggregatePolicy;
import glint.geometry.Bvh;
import glint.geometry.FlatList;
import glint.geometry.Primitives;
import glint.scene.Scene;
import java.util.Random;
import java.util.function.Function;
import org.junit.jupiter.api.Test;

/**
 * Every ray asks one aggregate, so an image does not depend on which one: rendered through the
 * hierarchy and through brute force, seeded random scenes give the same pixels.
 */
class AggregateRenderTest {

    private static final long SEED = 20_261_201L;

    @Test
    void theHierarchyAndBruteForceRenderTheSameImage() {
        Random random = new Random(SEED);
        for (int i = 0; i < 16; i++) {
            Scene scene = Renders.scene(RandomScenes.withSpheres(random, 40));
            Shading shading = i % 4 == 3 ? Shading.PHONG : Shading.COOK_TORRANCE;
            float[] brute = render(scene, shading, FlatList::new);
            float[] hierarchy = render(scene, shading, p -> new Bvh(p, 2));
            float[] chosen = render(scene, shading, AggregatePolicy::choose);
            assertSame(shading, brute, hierarchy, "scene " + i + " through the hierarchy");
            assertSame(shading, brute, chosen, "scene " + i + " through the aggregate the policy chose");
        }
    }

    /**
     * A glass sphere smaller than the offset rays leaving a surface start at: a ray refracted into
     * it starts past it, so the search inside it alone would lose what lies beyond.
     */
    @Test
    void aSphereSmallerThanTheOffsetRendersAsBruteForceDoes() {
        Scene scene = Renders.scene("""
                camera: {position: [0, 0.6, -0.3], look_at: [0, 0.3, 0], fov: 12}
                background: [0.2, 0.3, 0.9]
                lights: [{type: point, position: [-5, 8, -6], intensity: 100}]
                materials: {clear: {type: glass, ior: 1.5}}
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
                  - {type: sphere, center: [0, 0.3, 0], radius: 0.02, material: clear}
                """);
        for (Shading shading : Shading.values()) {
            float[] brute = render(scene, shading, FlatList::new, 0.05);
            float[] chosen = render(scene, shading, AggregatePolicy::choose, 0.05);
            assertSame(shading, brute, chosen, shading + ", offset 0.05 against a sphere 0.04 across");
        }
    }

    /**
     * Bit for bit under cook-torrance; under phong to float rounding, as a shadow ray multiplies the
     * glass it passes in the order it meets them.
     */
    private static void assertSame(Shading shading, float[] expected, float[] actual, String what) {
        if (shading == Shading.COOK_TORRANCE) {
            assertArrayEquals(expected, actual, what);
        } else {
            assertClose(expected, actual, what);
        }
    }

    private static float[] render(Scene scene, Shading shading, Function<Primitives, glint.geometry.Aggregate> of) {
        return render(scene, shading, of, Renders.EPSILON);
    }

    private static float[] render(Scene scene, Shading shading, Function<Primitives, glint.geometry.Aggregate> of,
                                  double epsilon) {
        RenderScene compiled = RenderScene.compile(scene, new RenderSettings(shading, 6, 0, epsilon), of);
        FrameBuffer frame = new FrameBuffer(48, 36);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(compiled, frame, 4, 0, 3);
        }
        return frame.rgb();
    }

    private static void assertClose(float[] expected, float[] actual, String what) {
        assertEquals(expected.length, actual.length);
        for (int i = 0; i < expected.length; i++) {
            assertTrue(Math.abs(expected[i] - actual[i]) <= 1e-6f * Math.max(1, Math.abs(expected[i])),
                    what + " value " + i + ": " + expected[i] + " against " + actual[i]);
        }
    }
}
