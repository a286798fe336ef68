package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import glint.config.Shading;
import glint.input.InputException;
import glint.render.RenderSettings.GlassFresnel;
import glint.scene.Scene;
import glint.scene.SceneLimits;
import glint.scene.SceneLoader;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A ray refracted into an empty glass sphere is followed from bounce to bounce by the geometry of
 * the chord (every bounce at the refracted ray's angle) instead of a search and a Fresnel
 * evaluation per bounce. The image is the one the searches give, to rounding, and the same rays are
 * counted: each scene is rendered as compiled and with every sphere's empty mark cleared, which
 * sends those rays through the search and the recursion.
 */
class InsideEmptySphereTest {

    /**
     * How far a pixel may differ, relative to its value or to {@link #DARK}, whichever is larger. A
     * searched ray starts inside the sphere, an offset of about 1e-9 in from the surface, while the
     * followed ray starts on it; shading amplifies that shift where it changes fast (a glossy
     * highlight, a surface lit at a grazing angle): up to 6e-6 in these scenes. A lost bounce, tint
     * or reflectance changes glass pixels by 1e-3 and more.
     */
    private static final double RELATIVE = 1e-4;
    private static final double DARK = 1e-3;

    @ParameterizedTest
    @CsvSource({"1, 5, 0.001", "4, 5, 0.001", "1, 5, 0", "1, 5, 0.01", "1, 2, 0.001", "1, 3, 0", "1, 8, 0"})
    void theDefaultScene(int samples, int depth, double minWeight) throws IOException, InputException {
        Scene scene = load("scenes/default.yaml");
        assertSameImage(scene, new RenderSettings(Shading.COOK_TORRANCE, depth, minWeight, Renders.EPSILON),
                161, 120, samples);
    }

    @Test
    void schlicksFresnel() throws IOException, InputException {
        assertSameImage(load("scenes/default.yaml"),
                new RenderSettings(Shading.COOK_TORRANCE, 6, 0, Renders.EPSILON).withGlassFresnel(GlassFresnel.SCHLICK),
                120, 90, 1);
    }

    @Test
    void aHierarchyOfGlassSpheres() throws IOException, InputException {
        assertSameImage(load("scenes/bench/glass-25.yaml"), settings(), 120, 90, 1);
    }

    @ParameterizedTest
    @ValueSource(strings = {"1.5, color: [1, 1, 1]", "2.42, color: [0.9, 0.6, 0.3]", "1.02, color: [0.5, 1, 0.8]",
            "0.75, color: [1, 1, 1]"})
    void tintedGlassDenseGlassAndABubble(String iorAndColor) {
        assertSameImage(Renders.scene("""
                camera: {position: [0.3, 1.4, -4], look_at: [0, 1, 0], fov: 50}
                lights: [{type: point, position: [-3, 6, -4], color: [1, 1, 1], intensity: 60}]
                objects:
                  - {type: sphere, center: [0, 1, 0], radius: 1, material: {type: glass, ior: %s}}
                  - {type: sphere, center: [2.1, 0.6, 1], radius: 0.6, material: {type: matte, color: [0.2, 0.5, 0.8]}}
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.6, 0.6, 0.6]}}
                """.formatted(iorAndColor)), settings(), 96, 72, 1);
    }

    @Test
    void randomScenesWithEmptyAndCutGlassSpheres() {
        Random random = new Random(20261122);
        for (int scene = 0; scene < 24; scene++) {
            assertSameImage(Renders.scene(RandomScenes.upToSixSpheres(random)), settings(), 67, 50, 1);
        }
    }

    @Test
    void randomGlassSpheresFloatingRestingAndSunk() {
        Random random = new Random(11222026);
        for (int scene = 0; scene < 16; scene++) {
            StringBuilder yaml = new StringBuilder("""
                    camera: {position: [0, 2, -7], look_at: [0, 0.8, 0], fov: 60}
                    lights: [{type: point, position: [-4, 7, -5], color: [1, 1, 1], intensity: 80}]
                    objects:
                      - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.6, 0.6, 0.6]}}
                      - {type: sphere, center: [0, 1, 3], radius: 1, material: {type: metal, color: [0.9, 0.9, 0.9], roughness: 0.2}}
                    """);
            for (int i = 0; i < 4; i++) {
                double radius = 0.3 + 0.6 * random.nextDouble();
                double height = radius * (0.5 + 2 * random.nextDouble()); // below the radius: sunk into the floor
                yaml.append(String.format(Locale.ROOT, "  - {type: sphere, center: [%.3f, %.3f, %.3f], radius: %.3f, "
                                + "material: {type: glass, ior: %.3f, color: [1, %.2f, %.2f]}}%n",
                        -3 + 2 * i + random.nextDouble(), height, 2 * random.nextDouble() - 1, radius,
                        1.05 + 1.5 * random.nextDouble(), 0.5 + 0.5 * random.nextDouble(), 0.5 + 0.5 * random.nextDouble()));
            }
            assertSameImage(Renders.scene(yaml.toString()), settings(), 80, 60, 1);
        }
    }

    @Test
    void onlyEmptySpheresAreFollowedByTheirGeometry() {
        // the outer glass sphere holds another: its rays must search; the inner one is empty
        Scene nested = Renders.scene("""
                camera: {position: [0, 1, -4], look_at: [0, 1, 0], fov: 50}
                lights: [{type: point, position: [-3, 6, -4], color: [1, 1, 1], intensity: 60}]
                objects:
                  - {type: sphere, center: [0, 1, 0], radius: 1.2, material: {type: glass, ior: 1.5}}
                  - {type: sphere, center: [0.2, 1, 0], radius: 0.5, material: {type: matte, color: [0.8, 0.2, 0.2]}}
                  - {type: sphere, center: [2.2, 0.5, 0.5], radius: 0.5, material: {type: glass, ior: 1.5}}
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.6, 0.6, 0.6]}}
                """);
        RenderScene compiled = RenderScene.compile(nested, settings());
        assertEquals("[false, false, true]", Arrays.toString(compiled.sphereIsEmpty));
        assertSameImage(nested, settings(), 96, 72, 1);
    }

    private static RenderSettings settings() {
        return new RenderSettings(Shading.COOK_TORRANCE, 5, 1e-3, Renders.EPSILON);
    }

    private static Scene load(String file) throws IOException, InputException {
        return SceneLoader.load(Path.of(file), SceneLimits.DEFAULT);
    }

    /** Renders the scene as compiled and with no sphere marked empty; compares every pixel and the rays cast. */
    private static void assertSameImage(Scene scene, RenderSettings settings, int width, int height, int samples) {
        FrameBuffer followed = new FrameBuffer(width, height);
        FrameBuffer searched = new FrameBuffer(width, height);
        long raysFollowed = Renders.renderCountingRays(RenderScene.compile(scene, settings), followed, samples);
        RenderScene withoutEmptySpheres = RenderScene.compile(scene, settings);
        Arrays.fill(withoutEmptySpheres.sphereIsEmpty, false);
        long raysSearched = Renders.renderCountingRays(withoutEmptySpheres, searched, samples);
        float[] a = followed.rgb(), b = searched.rgb();
        for (int i = 0; i < a.length; i++) {
            if (!(Math.abs(a[i] - b[i]) <= RELATIVE * Math.max(DARK, Math.abs(b[i])))) {
                int pixel = i / 3;
                fail("pixel (" + pixel % width + ", " + pixel / width + ") channel " + i % 3 + ": " + a[i]
                        + " followed through the sphere, " + b[i] + " searched");
            }
        }
        assertEquals(raysSearched, raysFollowed, "rays cast");
        assertTrue(raysFollowed >= (long) width * height * samples, "every camera ray is counted");
    }
}
