package glint.recipe;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import glint.math.Vector3d;
import glint.registry.Registry;
import glint.render.PinholeCamera;
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
     * white floor, seen from beside the light's path, so that its shadow on the floor lies in view,
     * and a sphere beside them, all found by one search.
     * A shadow ray from floor point (x, -1, z) travels along (0, 1, -1) / sqrt 2 and meets the disc's
     * plane (y + 0.25) - (z - 6) = 0 after (z - 5.25) / 2 along (0, 1, -1), at distance
     * sqrt(x^2 + (z - 6.75)^2 / 2) from the disc's centre: the shadow is the ellipse where that is at
     * most the radius 0.5. A camera ray to such a point passes the disc's plane more than 0.75 from
     * its centre, so nothing hides the shadow. The sphere, at x = -1.5, is out of the disc's way and
     * the disc out of its light's way (shadow rays keep their x).
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
        PinholeCamera camera = new PinholeCamera(Recipes.scene(REGISTRY, yaml).camera());
        // the disc faces the light: the matte preset's 0.8 / pi x irradiance 1 x cos 1, and ambient x 0.8
        assertColour(frame, pixel(camera, new Vector3d(0, -0.25, 6), w, h), 0.8 / Math.PI + 0.08,
                0.8 / Math.PI + 0.16, 0.8 / Math.PI + 0.24);
        // the floor at (0, -1, 6.7), 0.04 from the shadow's centre along z: ambient x 1 alone
        assertColour(frame, pixel(camera, new Vector3d(0, -1, 6.7), w, h), 0.1, 0.2, 0.3);
        // the floor at (1.5, -1, 6.7), beside the shadow: ambient + 1 / pi x irradiance 1 x cos 45 degrees
        double lit = 1 / Math.PI / Math.sqrt(2);
        assertColour(frame, pixel(camera, new Vector3d(1.5, -1, 6.7), w, h), 0.1 + lit, 0.2 + lit, 0.3 + lit);
        // the sphere's point that faces the light, centre + 0.5 (0, 1, -1) / sqrt 2: the pixel it lies in
        // shows the matte preset's 0.8 / pi x irradiance 1 x cos, at the point where that pixel's centre ray
        // meets the sphere, and ambient x 0.8
        Vector3d centre = new Vector3d(-1.5, -0.5, 6.7), towardsLight = new Vector3d(0, 1, -1).normalize();
        int[] spherePixel = pixel(camera, centre.add(towardsLight.scale(0.5)), w, h);
        Vector3d ray = camera.direction(spherePixel[0] + 0.5, spherePixel[1] + 0.5, w, h); // from the eye at 0
        double b = ray.dot(centre), t = b - Math.sqrt(b * b - centre.dot(centre) + 0.25); // the nearer root
        double cos = ray.scale(t).sub(centre).scale(1 / 0.5).dot(towardsLight);
        assertTrue(cos > 0.99, "the pixel sees the sphere near the point facing the light: cos " + cos);
        double sphere = 0.8 / Math.PI * cos;
        assertColour(frame, spherePixel, sphere + 0.08, sphere + 0.16, sphere + 0.24);
    }

    /** The pixel of a w x h image that {@code camera} sees world point {@code p} in. */
    private static int[] pixel(PinholeCamera camera, Vector3d p, int w, int h) {
        PinholeCamera.ImagePoint seen = camera.imagePoint(p, w, h).orElseThrow();
        return new int[] {seen.column(), seen.row()};
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
        PinholeCamera camera = new PinholeCamera(Recipes.scene(registry, yaml).camera());
        double lit = 2 / Math.PI;
        for (double x : new double[] {-1.5, 0, 1.5}) {
            assertColour(frame, pixel(camera, new Vector3d(x, 0.8, 5), w, h), lit, 0, 0);
        }
        for (double x : new double[] {-0.75, 0.75}) {
            assertColour(frame, pixel(camera, new Vector3d(x, -0.8, 5), w, h), 0, lit, 0);
        }
        // between the second row's discs: the wall
        assertColour(frame, pixel(camera, new Vector3d(0, -0.8, 5), w, h), 0, 0, lit);
        assertEquals("recipe.yaml:2:64: count must be a whole number from 1 to 100, got 2.5",
                Recipes.error(registry, "objects:\n  - {type: disc_row, first: [0, 0, 5], step: [1, 0, 0], count: 2.5, radius: 1}\n"));
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
