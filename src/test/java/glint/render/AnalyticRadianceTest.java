package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import org.junit.jupiter.api.Test;

/** Rendered radiance against values computed by hand from the definitions of docs/conventions.md. */
class AnalyticRadianceTest {

    /** A red Lambert sphere at (0, 0, 5), radius 1, lit by a point light of intensity 50 at (3, 4, 0). */
    private static final String LAMBERT_SCENE = """
            camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 40}
            lights:
              - {type: point, position: [3, 4, 0], color: [1, 1, 1], intensity: 50}
            objects:
              - {type: sphere, center: [0, 0, 5], radius: 1, material: {type: matte, color: [0.8, 0.4, 0.2]}}
            """;

    @Test
    void lambertSphereUnderPointLightMatchesHandComputedRadiance() {
        int w = 64, h = 48;
        FrameBuffer frame = Renders.render(LAMBERT_SCENE, w, h, 1, 1, Shading.COOK_TORRANCE);
        int[][] pixels = {{32, 24}, {36, 20}, {28, 27}, {38, 22}, {33, 18}};
        int checked = 0;
        for (int[] p : pixels) {
            double[] d = Renders.axisCameraRay(40, w, h, p[0], p[1]);
            // |t d - c|^2 = 1 with c = (0,0,5): t^2 - 10 t dz + 24 = 0, nearer root
            double b = 5 * d[2];
            double disc = b * b - 24;
            assertTrue(disc > 0, "pixel chosen to hit the sphere");
            double t = b - Math.sqrt(disc);
            double px = t * d[0], py = t * d[1], pz = t * d[2];
            double nx = px, ny = py, nz = pz - 5;
            double lx = 3 - px, ly = 4 - py, lz = -pz;
            double dist2 = lx * lx + ly * ly + lz * lz;
            double cos = (nx * lx + ny * ly + nz * lz) / Math.sqrt(dist2);
            double expectedRed = 0.8 / Math.PI * 50 / dist2 * Math.max(0, cos);
            assertEquals(expectedRed, frame.get(p[0], p[1], 0), 1e-5 * Math.max(1, expectedRed));
            assertEquals(expectedRed / 2, frame.get(p[0], p[1], 1), 1e-5 * Math.max(1, expectedRed));
            assertEquals(expectedRed / 4, frame.get(p[0], p[1], 2), 1e-5 * Math.max(1, expectedRed));
            checked += cos > 0 ? 1 : 0;
        }
        assertTrue(checked >= 3, "most chosen pixels are lit");
    }

    @Test
    void mirrorSphereShowsTheLitPlaneBehindTheCamera() {
        // The centre ray hits the mirror at (0,0,4) head-on and returns along -z to the plane z = -10.
        // Directional light travelling along (0.6, 0, -0.8): irradiance 2 * 0.8 on the plane.
        String yaml = """
                camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 10}
                lights:
                  - {type: directional, direction: [0.6, 0, -0.8], intensity: 2}
                objects:
                  - {type: sphere, center: [0, 0, 5], radius: 1, material: {type: metal, color: [1, 1, 1], roughness: 0}}
                  - {type: plane, point: [0, 0, -10], normal: [0, 0, 1], material: {type: matte, color: [0.25, 0.5, 0.75]}}
                """;
        FrameBuffer frame = Renders.render(yaml, 9, 9, 1, 2, Shading.COOK_TORRANCE);
        double e = 2 * 0.8;
        assertEquals(0.25 / Math.PI * e, frame.get(4, 4, 0), 1e-7); // frame buffer holds floats
        assertEquals(0.50 / Math.PI * e, frame.get(4, 4, 1), 1e-7); // frame buffer holds floats
        assertEquals(0.75 / Math.PI * e, frame.get(4, 4, 2), 1e-7); // frame buffer holds floats

        FrameBuffer direct = Renders.render(yaml, 9, 9, 1, 1, Shading.COOK_TORRANCE);
        assertEquals(0, direct.get(4, 4, 0), "depth 1 follows no reflection: the mirror is black");
    }

    /**
     * Rough glass seen head-on, lit from behind the eye: Whitted's light loop lights its reflection lobe,
     * f = D(n) F0 G2 / 4 with D(n) = 1 / (pi alpha^2), G2 = 1 and F0 = 0.04 (ior 1.5), untinted by the
     * colour, times the irradiance 2. Smooth glass has no highlight; phong reads no roughness.
     */
    @Test
    void roughGlassHeadOnShowsItsReflectionLobesHighlightByHand() {
        String yaml = """
                camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 10}
                lights:
                  - {type: directional, direction: [0, 0, 1], intensity: 2}
                objects:
                  - {type: sphere, center: [0, 0, 5], radius: 1, material: {type: glass, color: [1, 0.5, 0.25], roughness: %s}}
                """;
        FrameBuffer rough = Renders.render(yaml.formatted("0.5"), 9, 9, 1, 1, Shading.COOK_TORRANCE);
        double alpha = 0.25, expected = 0.04 / (Math.PI * alpha * alpha) / 4 * 2;
        for (int channel = 0; channel < 3; channel++) {
            assertEquals(expected, rough.get(4, 4, channel), 1e-6, "channel " + channel);
        }
        FrameBuffer smooth = Renders.render(yaml.formatted("0"), 9, 9, 1, 1, Shading.COOK_TORRANCE);
        assertEquals(0, smooth.get(4, 4, 0));
        FrameBuffer roughPhong = Renders.render(yaml.formatted("0.5"), 9, 9, 1, 3, Shading.PHONG);
        FrameBuffer smoothPhong = Renders.render(yaml.formatted("0"), 9, 9, 1, 3, Shading.PHONG);
        for (int y = 0; y < 9; y++) {
            for (int x = 0; x < 9; x++) {
                assertEquals(smoothPhong.get(x, y, 1), roughPhong.get(x, y, 1));
            }
        }
    }

    @Test
    void cameraRaysOfAKnownFovHitKnownPoints() {
        // fov 90 -> the image plane at z = 1 spans x in [-1, 1]. A small sphere placed on the ray
        // through pixel (i, j) shows in that pixel and not in pixels two away.
        int w = 40, h = 30;
        int[][] targets = {{0, 0}, {39, 29}, {30, 5}, {20, 15}};
        for (int[] target : targets) {
            double[] d = Renders.axisCameraRay(90, w, h, target[0], target[1]);
            double cx = 20 * d[0], cy = 20 * d[1], cz = 20 * d[2];
            String yaml = """
                    camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 90}
                    background: [0, 0, 0]
                    ambient: [1, 1, 1]
                    objects:
                      - {type: sphere, center: [%s, %s, %s], radius: 0.2, material: {type: matte, color: [1, 1, 1]}}
                    """.formatted(cx, cy, cz);
            FrameBuffer frame = Renders.render(yaml, w, h, 1, 1, Shading.COOK_TORRANCE);
            assertEquals(1, frame.get(target[0], target[1], 0), 1e-12, "sphere seen at " + target[0] + "," + target[1]);
            int farX = target[0] + (target[0] < 20 ? 3 : -3);
            assertEquals(0, frame.get(farX, target[1], 0), "nothing seen three pixels away");
        }
    }

    @Test
    void imageRightIsPlusXAndTopIsPlusY() {
        String yaml = """
                camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 90}
                ambient: [1, 1, 1]
                objects:
                  - {type: sphere, center: [3, 0, 10], radius: 1, material: {type: matte, color: [1, 0, 0]}}
                  - {type: sphere, center: [0, 3, 10], radius: 1, material: {type: matte, color: [0, 1, 0]}}
                """;
        FrameBuffer frame = Renders.render(yaml, 21, 21, 1, 1, Shading.COOK_TORRANCE);
        // x = 3 at z = 10 is 0.3 of the half-width right of centre: pixel 10 + 0.3 * 10.5 ~ 13
        assertEquals(1, frame.get(13, 10, 0), 1e-12);
        assertEquals(1, frame.get(10, 7, 1), 1e-12);
        assertEquals(0, frame.get(7, 10, 0), 1e-12);
    }
}
