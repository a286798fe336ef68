package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.geometry.Intersect;
import glint.image.FrameBuffer;
import org.junit.jupiter.api.Test;

/** Where textbook methods fail: far spheres, huge spheres, grazing planes, a camera inside glass. */
class StabilityTest {

    @Test
    void unitSphereAMillionUnitsAwayIsHitWhereItShouldBe() {
        double distance = 1e6;
        // head-on: t = distance - 1 exactly
        assertEquals(distance - 1, Intersect.sphereBefore(0, 0, distance, 1, 0, 0, 0, 0, 0, 1, Intersect.MISS), 1e-9);
        // off-axis rays at angles up to 0.9 of the angular radius: the hit lies on the sphere
        for (int i = -9; i <= 9; i++) {
            double angle = i / 10.0 * Math.asin(1 / distance);
            double dy = Math.sin(angle), dz = Math.cos(angle);
            double t = Intersect.sphereBefore(0, 0, distance, 1, 0, 0, 0, 0, dy, dz, Intersect.MISS);
            double py = t * dy, pz = t * dz - distance;
            assertEquals(1, Math.sqrt(py * py + pz * pz), 1e-9, "hit on the surface at ray " + i);
            // analytic nearer root of t^2 - 2 t D cos(a) + D^2 - 1 = 0, in a cancellation-free form
            double b = distance * dz;
            double c = distance * distance - 1;
            double root = Math.sqrt(1 - (distance * dy) * (distance * dy));
            assertEquals(c / (b + root), t, 1e-9 * distance);
        }
        // just outside the angular radius: a miss
        double miss = 1.0001 * Math.asin(1 / distance);
        assertEquals(Intersect.MISS, Intersect.sphereBefore(0, 0, distance, 1, 0, 0, 0, 0, Math.sin(miss), Math.cos(miss),
                Intersect.MISS));
    }

    @Test
    void farSphereFillsExactlyItsAnalyticDiscInTheImage() {
        double distance = 1e6;
        int w = 41, h = 41;
        double fov = Math.toDegrees(2 * Math.atan(2 / distance)); // disc radius ~ a quarter of the width
        String yaml = """
                camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: %s}
                ambient: [1, 1, 1]
                objects:
                  - {type: sphere, center: [0, 0, %s], radius: 1, material: {type: matte, color: [1, 1, 1]}}
                """.formatted(fov, distance);
        FrameBuffer frame = Renders.render(yaml, w, h, 1, 1, Shading.COOK_TORRANCE);
        double sinAngular = 1 / distance;
        int wrong = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double[] d = Renders.axisCameraRay(fov, w, h, x, y);
                double sinOff = Math.sqrt(d[0] * d[0] + d[1] * d[1]);
                boolean inside = sinOff < sinAngular * (1 - 1e-6);
                boolean outside = sinOff > sinAngular * (1 + 1e-6);
                double v = frame.get(x, y, 0);
                if ((inside && v != 1) || (outside && v != 0)) {
                    wrong++;
                }
            }
        }
        assertEquals(0, wrong);
    }

    @Test
    void hugeGroundSphereShowsNoAcneAndNoHoles() {
        for (double r : new double[] {1e4, 1e7, 1e8}) {
            hugeGroundSphere(r);
        }
    }

    private static void hugeGroundSphere(double r) {
        String yaml = """
                camera: {position: [0, 1, -5], look_at: [0, 0, 5], fov: 70}
                lights:
                  - {type: point, position: [2, 6, 3], intensity: 40}
                objects:
                  - {type: sphere, center: [0, %s, 0], radius: %s, material: {type: matte, color: [0.5, 0.5, 0.5]}}
                """.formatted(-r, r);
        int w = 80, h = 60;
        FrameBuffer frame = Renders.render(yaml, w, h, 1, 1, Shading.COOK_TORRANCE);
        assertGroundMatchesLambert(frame, w, h, 70, new double[] {0, 1, -5}, new double[] {0, 0, 5},
                (ox, oy, oz, dx, dy, dz) -> Intersect.sphereBefore(0, -r, 0, r, ox, oy, oz, dx, dy, dz, Intersect.MISS),
                (px, py, pz) -> normalize(px, py + r, pz), new double[] {2, 6, 3}, 40, 0.5);
    }

    @Test
    void planeSeenAtGrazingAnglesShowsNoAcneAndNoHoles() {
        String yaml = """
                camera: {position: [0, 0.01, 0], look_at: [0, 0.005, 1], fov: 50}
                lights:
                  - {type: point, position: [0, 5, 50], intensity: 500}
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.5, 0.5, 0.5]}}
                """;
        int w = 80, h = 60;
        FrameBuffer frame = Renders.render(yaml, w, h, 1, 1, Shading.COOK_TORRANCE);
        assertGroundMatchesLambert(frame, w, h, 50, new double[] {0, 0.01, 0}, new double[] {0, 0.005, 1},
                (ox, oy, oz, dx, dy, dz) -> Intersect.planeBefore(0, 1, 0, 0, ox, oy, oz, dx, dy, dz, Intersect.MISS),
                (px, py, pz) -> new double[] {0, 1, 0}, new double[] {0, 5, 50}, 500, 0.5);
    }

    @Test
    void cameraInsideAGlassSphereRendersWithoutNaN() {
        String yaml = """
                camera: {position: [0, 1, 0], look_at: [0, 0.5, 1], fov: 120}
                background: [0.1, 0.2, 0.3]
                lights:
                  - {type: point, position: [0, 5, 0], intensity: 50}
                  - {type: directional, direction: [0, -1, 0]}
                objects:
                  - {type: sphere, center: [0, 1, 0], radius: 2, material: glass}
                  - {type: sphere, center: [0, 1, 0.5], radius: 0.3, material: {type: metal, roughness: 0.001}}
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
                """;
        for (Shading shading : Shading.values()) {
            FrameBuffer frame = Renders.render(yaml, 48, 36, 4, 12, shading);
            for (float v : frame.rgb()) {
                assertTrue(Float.isFinite(v) && v >= 0, "finite, non-negative radiance under " + shading);
            }
        }
    }

    interface Hit {
        double t(double ox, double oy, double oz, double dx, double dy, double dz);
    }

    interface Normal {
        double[] at(double px, double py, double pz);
    }

    /** Every pixel whose ray meets the surface shows the Lambert radiance computed analytically. */
    private static void assertGroundMatchesLambert(FrameBuffer frame, int w, int h, double fov, double[] eye,
                                                   double[] lookAt, Hit hit, Normal normal, double[] light,
                                                   double intensity, double albedo) {
        glint.scene.Camera camera = glint.scene.Camera.lookAt(new glint.math.Vector3d(eye[0], eye[1], eye[2]),
                new glint.math.Vector3d(lookAt[0], lookAt[1], lookAt[2]), glint.math.Vector3d.UNIT_Y, fov);
        int surfacePixels = 0, wrong = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                glint.math.Vector3d d = new PinholeCamera(camera).direction(x + 0.5, y + 0.5, w, h);
                double t = hit.t(eye[0], eye[1], eye[2], d.x(), d.y(), d.z());
                double v = frame.get(x, y, 0);
                if (t == Intersect.MISS) {
                    wrong += v == 0 ? 0 : 1;
                    continue;
                }
                surfacePixels++;
                double px = eye[0] + t * d.x(), py = eye[1] + t * d.y(), pz = eye[2] + t * d.z();
                double[] n = normal.at(px, py, pz);
                double lx = light[0] - px, ly = light[1] - py, lz = light[2] - pz;
                double dist2 = lx * lx + ly * ly + lz * lz;
                double cos = (n[0] * lx + n[1] * ly + n[2] * lz) / Math.sqrt(dist2);
                double expected = albedo / Math.PI * intensity / dist2 * Math.max(0, cos);
                if (Math.abs(v - expected) > 1e-4 * expected + 1e-7) {
                    wrong++;
                }
            }
        }
        assertTrue(surfacePixels > w * h / 4, "the surface fills a good part of the image");
        assertEquals(0, wrong, "pixels differing from the analytic radiance (acne or holes)");
    }

    private static double[] normalize(double x, double y, double z) {
        double len = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / len, y / len, z / len};
    }
}
