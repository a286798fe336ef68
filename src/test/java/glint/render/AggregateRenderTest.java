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
        RenderScene compiled = RenderScene.compile(scene, new RenderSettings(shading, 6, 0, Renders.EPSILON), of);
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
