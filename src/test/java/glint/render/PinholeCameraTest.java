package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.math.Vector3d;
import glint.scene.Camera;
import java.util.Optional;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The camera's rays against their definition: angles worked out by hand, on seeded random cameras; and the
 * image point of a world point, its inverse.
 */
class PinholeCameraTest {

    private static final double EPS = 1e-12;

    /** A camera somewhere, looking somewhere, with a field of view in [5, 150] degrees. */
    private static Camera randomCamera(SplittableRandom random) {
        Vector3d eye = new Vector3d(random.nextDouble(-50, 50), random.nextDouble(-50, 50), random.nextDouble(-50, 50));
        double[] towards = RandomScenes.unitVector(random);
        Vector3d target = eye.add(new Vector3d(towards[0], towards[1], towards[2]));
        return Camera.lookAt(eye, target, Vector3d.UNIT_Y, random.nextDouble(5, 150));
    }

    private static double angleDegrees(Vector3d a, Vector3d b) {
        return Math.toDegrees(Math.atan2(a.cross(b).length(), a.dot(b)));
    }

    @Test
    void theRayThroughTheImagesCentreIsTheViewDirection() {
        SplittableRandom random = new SplittableRandom(43);
        for (int trial = 0; trial < 200; trial++) {
            Camera camera = randomCamera(random);
            int width = 1 + random.nextInt(900), height = 1 + random.nextInt(700);
            Vector3d centre = new PinholeCamera(camera).direction(width / 2.0, height / 2.0, width, height);
            assertEquals(0, angleDegrees(camera.orientation().forward(), centre), 1e-9, camera::toString);
            assertEquals(1, centre.length(), EPS);
        }
    }

    @Test
    void theImagesLeftAndRightEdgesAreHalfTheFieldOfViewOffTheViewDirection() {
        SplittableRandom random = new SplittableRandom(44);
        for (int trial = 0; trial < 200; trial++) {
            Camera camera = randomCamera(random);
            PinholeCamera pinhole = new PinholeCamera(camera);
            int width = 1 + random.nextInt(900), height = 1 + random.nextInt(700);
            Vector3d forward = camera.orientation().forward();
            Vector3d left = pinhole.direction(0, height / 2.0, width, height);
            Vector3d right = pinhole.direction(width, height / 2.0, width, height);
            assertEquals(camera.fovDegrees() / 2, angleDegrees(forward, left), 1e-9);
            assertEquals(camera.fovDegrees() / 2, angleDegrees(forward, right), 1e-9);
            assertEquals(camera.fovDegrees(), angleDegrees(left, right), 1e-9);
            // the vertical field of view follows from the aspect: tan(vertical / 2) = tan(fov / 2) height / width
            Vector3d top = pinhole.direction(width / 2.0, 0, width, height);
            double tanHalf = Math.tan(Math.toRadians(camera.fovDegrees()) / 2);
            assertEquals(Math.toDegrees(Math.atan(tanHalf * height / width)), angleDegrees(forward, top), 1e-9);
        }
    }

    @Test
    void lookingAlongZWithUpYPlusXIsOnTheImagesRightAndPlusYAtItsTop() {
        double tanHalf = Math.tan(Math.toRadians(90) / 2); // 1
        PinholeCamera camera = new PinholeCamera(Camera.lookAt(Vector3d.ZERO, Vector3d.UNIT_Z, Vector3d.UNIT_Y, 90));
        int width = 200, height = 100;
        SplittableRandom random = new SplittableRandom(45);
        for (int trial = 0; trial < 200; trial++) {
            double px = random.nextDouble(0, width), py = random.nextDouble(0, height);
            Vector3d d = camera.direction(px, py, width, height);
            // the screen one unit ahead spans x in [-1, 1] left to right and y in [0.5, -0.5] top to bottom
            assertTrue(d.z() > 0);
            assertEquals((2 * px / width - 1) * tanHalf, d.x() / d.z(), EPS, "x at " + px);
            assertEquals((1 - 2 * py / height) * tanHalf * height / width, d.y() / d.z(), EPS, "y at " + py);
        }
        Vector3d topRight = camera.direction(width, 0, width, height);
        assertEquals(1, topRight.x() / topRight.z(), EPS);
        assertEquals(0.5, topRight.y() / topRight.z(), EPS);
        assertEquals(Vector3d.ZERO, camera.eye());
    }

    @Test
    void theImagePointOfAPointOnARayIsWhereTheRayWasAimed() {
        SplittableRandom random = new SplittableRandom(46);
        for (int trial = 0; trial < 500; trial++) {
            Camera camera = randomCamera(random);
            PinholeCamera pinhole = new PinholeCamera(camera);
            int width = 1 + random.nextInt(900), height = 1 + random.nextInt(700);
            double px = random.nextDouble(-width, 2 * width), py = random.nextDouble(-height, 2 * height);
            double along = random.nextDouble(0.01, 100);
            Vector3d p = pinhole.eye().add(pinhole.direction(px, py, width, height).scale(along));
            PinholeCamera.ImagePoint seen = pinhole.imagePoint(p, width, height).orElseThrow();
            String where = camera + " " + width + "x" + height + " at " + px + ", " + py;
            assertEquals(px, seen.px(), 1e-9 * (width + Math.abs(px)), where);
            assertEquals(py, seen.py(), 1e-9 * (height + Math.abs(py)), where);
        }
    }

    @Test
    void lookingAlongZThePointsOfTheScreenOneUnitAheadAreSeenWhereTheyLie() {
        // fov 90: the screen at z = 1 spans x in [-1, 1] left to right and y in [0.5, -0.5] top to bottom
        PinholeCamera camera = new PinholeCamera(Camera.lookAt(Vector3d.ZERO, Vector3d.UNIT_Z, Vector3d.UNIT_Y, 90));
        int width = 200, height = 100;
        assertImagePoint(100, 50, camera.imagePoint(new Vector3d(0, 0, 7), width, height));
        assertImagePoint(200, 0, camera.imagePoint(new Vector3d(1, 0.5, 1), width, height));
        assertImagePoint(0, 100, camera.imagePoint(new Vector3d(-3, -1.5, 3), width, height));
        assertImagePoint(150, 75, camera.imagePoint(new Vector3d(1, -0.5, 2), width, height));
        assertImagePoint(400, 50, camera.imagePoint(new Vector3d(3, 0, 1), width, height)); // outside the view
        PinholeCamera.ImagePoint inPixel = camera.imagePoint(new Vector3d(-0.5, 0.25, 1), width, height).orElseThrow();
        assertEquals(50, inPixel.column());
        assertEquals(25, inPixel.row());
        assertTrue(camera.imagePoint(new Vector3d(0, 0, -1), width, height).isEmpty(), "behind the eye");
        assertTrue(camera.imagePoint(new Vector3d(1, 2, 0), width, height).isEmpty(), "on the eye's plane");
        assertTrue(camera.imagePoint(Vector3d.ZERO, width, height).isEmpty(), "the eye itself");
    }

    private static void assertImagePoint(double px, double py, Optional<PinholeCamera.ImagePoint> seen) {
        assertEquals(px, seen.orElseThrow().px(), EPS);
        assertEquals(py, seen.orElseThrow().py(), EPS);
    }
}
