package glint.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.accel.AggregatePolicy;
import glint.accel.Bvh;
import glint.accel.FlatList;
import glint.accel.LightCells;
import glint.geometry.Primitives;
import glint.image.FrameBuffer;
import glint.scene.Scene;
import java.util.Random;
import java.util.function.Function;
import org.junit.jupiter.api.Assertions;
import org.junit.jupiter.api.Test;

/**
 * An image does not depend on which aggregate its rays ask: rendered through the hierarchy, through
 * brute force and through what the policy chooses (shadow rays towards a point light through its
 * direction cells), seeded random scenes give the same pixels; where the chosen aggregate knows a
 * glass sphere's inside is empty and the glass walks it in closed form ({@link InsideWalk}), the same
 * to float rounding.
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
            float[] chosen = render(scene, shading, null);
            assertSame(shading, brute, hierarchy, "scene " + i + " through the hierarchy");
            assertSameToRounding(brute, chosen, "scene " + i + " through the aggregate the policy chose");
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
            float[] chosen = render(scene, shading, null, 0.05);
            assertSame(shading, brute, chosen, shading + ", offset 0.05 against a sphere 0.04 across");
        }
    }

    /**
     * A point light's shadow rays ask its direction cells in front of the scene's aggregate; a
     * directional light's, those of the point lights past the first few, and every light's in a scene
     * of more primitives than the policy gives cells, ask the scene's aggregate.
     */
    @Test
    void shadowRaysAskTheAggregateChosenForTheirLight() {
        String camera = "camera: {position: [0, 1, -6], look_at: [0, 1, 0], fov: 50}\n";
        String lights = """
                lights:
                  - {type: point, position: [-5, 8, -6], intensity: 100}
                  - {type: directional, direction: [1, -1, 0.5], intensity: 1}
                """;
        String floor = "objects:\n  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}\n";
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, 6, 0, Renders.EPSILON);
        RenderScene small = RenderScene.compile(Renders.scene(camera + lights + floor + spheres(3)), settings);
        assertTrue(small.shadowAggregate[0] instanceof LightCells, small.shadowAggregate[0].toString());
        Assertions.assertSame(small.aggregate, small.shadowAggregate[1]);
        int most = AggregatePolicy.MOST_LIGHT_CELL_PRIMITIVES;
        RenderScene large = RenderScene.compile(Renders.scene(camera + lights + floor + spheres(most)), settings);
        Assertions.assertSame(large.aggregate, large.shadowAggregate[0], "a plane and " + most + " spheres");
        Assertions.assertSame(large.aggregate, large.shadowAggregate[1]);
        StringBuilder many = new StringBuilder("lights:\n");
        for (int i = 0; i <= AggregatePolicy.MOST_CELL_LIGHTS; i++) {
            many.append("  - {type: point, position: [").append(i).append(", 8, -6], intensity: 10}\n");
        }
        RenderScene crowded = RenderScene.compile(Renders.scene(camera + many + floor + spheres(3)), settings);
        for (int i = 0; i < AggregatePolicy.MOST_CELL_LIGHTS; i++) {
            assertTrue(crowded.shadowAggregate[i] instanceof LightCells, "point light " + i);
        }
        Assertions.assertSame(crowded.aggregate, crowded.shadowAggregate[AggregatePolicy.MOST_CELL_LIGHTS]);
    }

    /** Objects lines for n spheres in a row along x. */
    private static String spheres(int n) {
        StringBuilder yaml = new StringBuilder();
        for (int i = 0; i < n; i++) {
            yaml.append("  - {type: sphere, center: [").append(i).append(", 1, 0], radius: 0.4}\n");
        }
        return yaml.toString();
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

    /** A relative mean square error of at most 1e-8: the same image to float rounding. */
    private static void assertSameToRounding(float[] expected, float[] actual, String what) {
        double error = 0, energy = 0;
        for (int i = 0; i < expected.length; i++) {
            double d = expected[i] - actual[i];
            error += d * d;
            energy += (double) expected[i] * expected[i];
        }
        assertTrue(error <= 1e-8 * energy, what + ": relative mean square error " + error / energy);
    }

    private static float[] render(Scene scene, Shading shading, Function<Primitives, glint.accel.Aggregate> of) {
        return render(scene, shading, of, Renders.EPSILON);
    }

    /** Rendered through the aggregate {@code of} builds, or with null through what the policy chooses. */
    private static float[] render(Scene scene, Shading shading, Function<Primitives, glint.accel.Aggregate> of,
                                  double epsilon) {
        RenderSettings settings = new RenderSettings(shading, 6, 0, epsilon);
        RenderScene compiled = of == null ? RenderScene.compile(scene, settings)
                : RenderScene.compile(scene, settings, of);
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
