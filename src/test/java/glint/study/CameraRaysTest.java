package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;

import glint.math.Quaternion;
import glint.math.Vector3d;
import org.junit.jupiter.api.Test;

/** The reference camera rays of the studies and tests. */
class CameraRaysTest {

    private static void assertVector(Vector3d expected, Vector3d actual, double tolerance) {
        assertEquals(expected.x(), actual.x(), tolerance, "x of " + actual);
        assertEquals(expected.y(), actual.y(), tolerance, "y of " + actual);
        assertEquals(expected.z(), actual.z(), tolerance, "z of " + actual);
    }

    @Test
    void cameraRayThroughTheCentreIsForwardAndThroughTheRightEdgeAtHalfTheFov() {
        Quaternion q = Quaternion.IDENTITY;
        assertVector(Vector3d.UNIT_Z, CameraRays.direction(q, 90, 100, 50, 50, 25), 1e-15);
        double s = Math.sqrt(0.5);
        assertVector(new Vector3d(s, 0, s), CameraRays.direction(q, 90, 100, 50, 100, 25), 1e-15);
        // vertical extent follows the aspect: top edge at tan = 0.5
        Vector3d top = CameraRays.direction(q, 90, 100, 50, 50, 0);
        assertEquals(0.5, top.y() / top.z(), 1e-15);
    }
}
