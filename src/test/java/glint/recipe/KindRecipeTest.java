package glint.recipe;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import glint.registry.Registry;
import glint.render.Renders;
import org.junit.jupiter.api.Test;

/** The primitive-kind recipe followed in test sources: a disc read, compiled and rendered. */
class KindRecipeTest {

    private static final Registry REGISTRY = Registry.STANDARD.with(DiscType.TYPE);

    /**
     * A matte disc of albedo (0.5, 0.25, 1) facing the camera at z = 5, radius 1, under a
     * directional light of intensity 2 shining along its normal, before a background.
     */
    private static final String SCENE = """
            camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 40}
            background: [0.1, 0.2, 0.3]
            lights:
              - {type: directional, direction: [0, 0, 1], intensity: 2}
            objects:
              - {type: disc, center: [0, 0, 5], normal: [0, 0, -1], radius: 1, material: {type: matte, color: [0.5, 0.25, 1]}}
            """;

    @Test
    void aDiscShowsLambertRadianceInsideItsRadiusAndTheBackgroundOutside() {
        int w = 40, h = 30;
        FrameBuffer frame = Recipes.render(REGISTRY, SCENE, w, h, 1);
        int inside = 0, outside = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double[] d = Renders.axisCameraRay(40, w, h, x, y);
                double t = 5 / d[2];
                double r = Math.hypot(t * d[0], t * d[1]); // distance from the disc's centre on its plane
                if (r < 0.98) {
                    // Lambert: albedo / pi x irradiance 2 x cos 1
                    assertEquals(0.5 / Math.PI * 2, frame.get(x, y, 0), 1e-6);
                    assertEquals(0.25 / Math.PI * 2, frame.get(x, y, 1), 1e-6);
                    assertEquals(1 / Math.PI * 2, frame.get(x, y, 2), 1e-6);
                    inside++;
                } else if (r > 1.02) {
                    assertEquals(0.1f, frame.get(x, y, 0));
                    assertEquals(0.3f, frame.get(x, y, 2));
                    outside++;
                }
            }
        }
        assertTrue(inside > 20 && outside > 20, inside + " pixels inside, " + outside + " outside");
    }

    /**
     * A disc tilted to face a directional light that shines down at 45 degrees towards +z, above a
     * white floor, seen from beside the light's path, so that its shadow on the floor lies in view.
     * A shadow ray from floor point (x, -1, z) travels along (0, 1, -1) / sqrt 2 and meets the disc's
     * plane (y + 0.25) - (z - 6) = 0 after (z - 5.25) / 2 along (0, 1, -1), at distance
     * sqrt(x^2 + (z - 6.75)^2 / 2) from the disc's centre: the shadow is the ellipse where that is at
     * most the radius 0.5. A camera ray to such a point passes the disc's plane more than 0.75 from
     * its centre, so nothing hides the shadow.
     */
    @Test
    void aDiscCastsAShadowInViewAndMeetsTheOtherKindsInOneSearch() {
        String yaml = """
                camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 40}
                ambient: [0.1, 0.2, 0.3]
                lights:
                  - {type: directional, direction: [0, -1, 1], intensity: 1}
                objects:
                  - {type: disc, center: [0, -0.25, 6], normal: [0, 1, -1], radius: 0.5}
                  - {type: plane, point: [0, -1, 0], normal: [0, 1, 0], material: {type: matte, color: [1, 1, 1]}}
                  - {type: sphere, center: [-1.5, -0.5, 6.7], radius: 0.5}
                """;
        int w = 80, h = 60;
        FrameBuffer frame = Recipes.render(REGISTRY, yaml, w, h, 1);
        // the disc faces the light: the matte preset's 0.8 / pi x irradiance 1 x cos 1, and ambient x 0.8
        assertColour(frame, pixel(0, -0.25 * 5 / 6, w, h), 0.8 / Math.PI + 0.08, 0.8 / Math.PI + 0.16,
                0.8 / Math.PI + 0.24);
        // the floor at (0, -1, 6.7), 0.04 from the shadow's centre along z: ambient x 1 alone
        assertColour(frame, floorPixel(0, 6.7, w, h), 0.1, 0.2, 0.3);
        // the floor at (1.5, -1, 6.7), beside the shadow: ambient + 1 / pi x irradiance 1 x cos 45 degrees
        double lit = 1 / Math.PI / Math.sqrt(2);
        assertColour(frame, floorPixel(1.5, 6.7, w, h), 0.1 + lit, 0.2 + lit, 0.3 + lit);
    }

    /** The pixel whose camera ray (the camera's as above) meets the floor y = -1 at (x, z). */
    private static int[] floorPixel(double x, double z, int w, int h) {
        return pixel(x * 5 / z, -5 / z, w, h);
    }

    @Test
    void aShapeOfManyPrimitivesGivesEachOfThemTheShapesMaterial() {
        // two rows of discs of their own colours before a blue wall, all facing a light along +z:
        // each disc's centre shows 1 / pi x irradiance 2 in its row's colour
        Registry registry = REGISTRY.with(DiscRowType.TYPE);
        String yaml = """
                camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 40}
                lights:
                  - {type: directional, direction: [0, 0, 1], intensity: 2}
                objects:
                  - {type: disc_row, first: [-1.5, 0.8, 5], step: [1.5, 0, 0], count: 3, radius: 0.5, material: {type: matte, color: [1, 0, 0]}}
                  - {type: plane, point: [0, 0, 10], normal: [0, 0, -1], material: {type: matte, color: [0, 0, 1]}}
                  - {type: disc_row, first: [-0.75, -0.8, 5], step: [1.5, 0, 0], count: 2, radius: 0.5, material: {type: matte, color: [0, 1, 0]}}
                """;
        int w = 80, h = 60;
        FrameBuffer frame = Recipes.render(registry, yaml, w, h, 1);
        double lit = 2 / Math.PI;
        for (double x : new double[] {-1.5, 0, 1.5}) {
            assertColour(frame, pixel(x, 0.8, w, h), lit, 0, 0);
        }
        for (double x : new double[] {-0.75, 0.75}) {
            assertColour(frame, pixel(x, -0.8, w, h), 0, lit, 0);
        }
        assertColour(frame, pixel(0, -0.8, w, h), 0, 0, lit); // between the second row's discs: the wall
        assertEquals("recipe.yaml:2:64: count must be a whole number from 1 to 100, got 2.5",
                Recipes.error(registry, "objects:\n  - {type: disc_row, first: [0, 0, 5], step: [1, 0, 0], count: 2.5, radius: 1}\n"));
    }

    /** The pixel (x, y) of a w x h image whose camera ray meets the point (x, y, 5), the camera's as above. */
    private static int[] pixel(double x, double y, int w, int h) {
        double half = Math.tan(Math.toRadians(20));
        return new int[] {(int) Math.floor((x / 5 / half + 1) / 2 * w),
            (int) Math.floor((1 - y / 5 / (half * h / w)) / 2 * h)};
    }

    private static void assertColour(FrameBuffer frame, int[] pixel, double r, double g, double b) {
        String where = "pixel " + pixel[0] + ", " + pixel[1];
        assertEquals(r, frame.get(pixel[0], pixel[1], 0), 1e-6, where);
        assertEquals(g, frame.get(pixel[0], pixel[1], 1), 1e-6, where);
        assertEquals(b, frame.get(pixel[0], pixel[1], 2), 1e-6, where);
    }

    @Test
    void aDiscIsReadWithTheLoadersChecksAndMessages() {
        assertEquals("recipe.yaml:2:5: missing required key 'radius' in disc",
                Recipes.error(REGISTRY, "objects:\n  - {type: disc, center: [0, 0, 5], normal: [0, 0, 1]}\n"));
        assertEquals("recipe.yaml:2:56: unknown key 'raduis' in disc (did you mean 'radius'?)",
                Recipes.error(REGISTRY, "objects:\n  - {type: disc, center: [0, 0, 5], normal: [0, 0, 1], raduis: 1}\n"));
        assertEquals("recipe.yaml:2:12: unknown object type 'disk' (did you mean 'disc'?)",
                Recipes.error(REGISTRY, "objects:\n  - {type: disk, center: [0, 0, 5]}\n"));
        assertEquals("recipe.yaml:2:56: normal must not be the zero vector",
                Recipes.error(REGISTRY, "objects:\n  - {type: disc, center: [0, 0, 5], radius: 1, normal: [0, 0, 0]}\n"));
    }
}
