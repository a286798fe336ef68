package glint.math;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The camera's orientation algebra. */
class QuaternionTest {

    private static void assertVector(Vector3d expected, Vector3d actual, double tolerance) {
        assertEquals(expected.x(), actual.x(), tolerance, "x of " + actual);
        assertEquals(expected.y(), actual.y(), tolerance, "y of " + actual);
        assertEquals(expected.z(), actual.z(), tolerance, "z of " + actual);
    }

    @Test
    void quarterTurnAboutYTakesForwardToRight() {
        Quaternion q = Quaternion.fromAxisAngle(Vector3d.UNIT_Y, Math.PI / 2);
        assertVector(new Vector3d(1, 0, 0), q.rotate(Vector3d.UNIT_Z), 1e-15);
    }

    @Test
    void lookRotationPointsForwardAlongTheViewAndKeepsUpUp() {
        Quaternion q = Quaternion.lookRotation(new Vector3d(1, 0, 1), Vector3d.UNIT_Y);
        double s = Math.sqrt(0.5);
        assertVector(new Vector3d(s, 0, s), q.forward(), 1e-15);
        assertVector(Vector3d.UNIT_Y, q.up(), 1e-15);
        assertVector(new Vector3d(s, 0, -s), q.right(), 1e-15);
        assertEquals(1, q.norm(), 1e-15);
    }

    @Test
    void lookRotationStraightDownAndIntoEachOctant() {
        Vector3d[] views = {new Vector3d(0, -1, 1e-3), new Vector3d(-1, -1, -1), new Vector3d(0, 0, -1),
                new Vector3d(-3, 2, 0.5)};
        for (Vector3d view : views) {
            Quaternion q = Quaternion.lookRotation(view, Vector3d.UNIT_Y);
            assertVector(view.normalize(), q.forward(), 1e-12);
            assertEquals(0, q.right().y(), 1e-12, "no roll: right stays horizontal");
        }
    }

    @Test
    void productComposesRotations() {
        Quaternion a = Quaternion.fromAxisAngle(new Vector3d(1, 2, 3), 0.7);
        Quaternion b = Quaternion.fromAxisAngle(new Vector3d(-2, 0.5, 1), 1.9);
        Vector3d v = new Vector3d(0.3, -1.2, 2.5);
        assertVector(a.rotate(b.rotate(v)), a.multiply(b).rotate(v), 1e-12);
    }
}
