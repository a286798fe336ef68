package glint.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.math.Quaternion;
import glint.math.Vector3d;
import glint.scene.Camera;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The camera flies in its own frame, by elapsed time, and its quaternion stays unit. */
class CameraControllerTest {

    private static final double SPEED = 2;       // units per second
    private static final double TURN = 60;       // degrees per second
    private static final double EPS = 1e-12;

    private final CameraController camera =
            new CameraController(new Camera(Vector3d.ZERO, Quaternion.IDENTITY, 60), SPEED, TURN);

    private static InputFrame hold(Action action, double seconds) {
        return new InputFrame.Builder().hold(action, seconds).build();
    }

    private static void assertVector(Vector3d expected, Vector3d actual, double tolerance) {
        assertEquals(expected.x(), actual.x(), tolerance, () -> "x of " + actual);
        assertEquals(expected.y(), actual.y(), tolerance, () -> "y of " + actual);
        assertEquals(expected.z(), actual.z(), tolerance, () -> "z of " + actual);
    }

    /** Turns by {@code degrees} with a held key at the configured rate. */
    private void turn(Action action, double degrees) {
        assertTrue(camera.apply(hold(action, degrees / TURN)));
    }

    @ParameterizedTest(name = "{0} moves along camera ({1}, {2}, {3})")
    @CsvSource({
        "FORWARD, 0, 0, 1", "BACK, 0, 0, -1", "LEFT, -1, 0, 0", "RIGHT, 1, 0, 0", "UP, 0, 1, 0", "DOWN, 0, -1, 0"})
    void eachMotionKeyMovesInTheCameraFrame(Action key, double x, double y, double z) {
        assertTrue(camera.apply(hold(key, 0.5)));
        assertVector(new Vector3d(x, y, z).scale(SPEED * 0.5), camera.camera().position(), EPS);
        assertEquals(Quaternion.IDENTITY, camera.camera().orientation());
    }

    @ParameterizedTest(name = "after turning right 90 degrees {0} moves along world ({1}, {2}, {3})")
    @CsvSource({
        "FORWARD, 1, 0, 0", "BACK, -1, 0, 0", "LEFT, 0, 0, 1", "RIGHT, 0, 0, -1", "UP, 0, 1, 0", "DOWN, 0, -1, 0"})
    void afterYawNinetyTheKeysFollowTheCamera(Action key, double x, double y, double z) {
        turn(Action.YAW_RIGHT, 90);
        assertVector(Vector3d.ZERO, camera.camera().position(), 0); // turning does not move
        camera.apply(hold(key, 1));
        assertVector(new Vector3d(x, y, z).scale(SPEED), camera.camera().position(), 1e-12);
    }

    @Test
    void afterLookingUpForwardIsWorldUp() {
        turn(Action.PITCH_UP, 90);
        camera.apply(hold(Action.FORWARD, 1));
        assertVector(new Vector3d(0, SPEED, 0), camera.camera().position(), 1e-12);
    }

    @Test
    void afterRollingLeftUpIsWorldLeft() {
        turn(Action.ROLL_LEFT, 90);
        assertVector(new Vector3d(0, 0, 1), camera.camera().orientation().forward(), 1e-12); // roll keeps the view
        camera.apply(hold(Action.UP, 1));
        assertVector(new Vector3d(-SPEED, 0, 0), camera.camera().position(), 1e-12);
    }

    @ParameterizedTest(name = "{0} turns forward to ({1}, {2}, {3})")
    @CsvSource({
        "YAW_RIGHT, 1, 0, 0", "YAW_LEFT, -1, 0, 0", "PITCH_UP, 0, 1, 0", "PITCH_DOWN, 0, -1, 0"})
    void arrowsTurnByTurnSpeedTimesTime(Action key, double x, double y, double z) {
        camera.apply(hold(key, 1.5)); // 60 degrees a second for 1.5 s: a right angle
        assertVector(new Vector3d(x, y, z), camera.camera().orientation().forward(), 1e-12);
    }

    @Test
    void rollTurnsTheUpVectorNotTheView() {
        camera.apply(hold(Action.ROLL_RIGHT, 1.5));
        Quaternion q = camera.camera().orientation();
        assertVector(new Vector3d(0, 0, 1), q.forward(), 1e-12);
        assertVector(new Vector3d(1, 0, 0), q.up(), 1e-12);
    }

    @Test
    void distanceIsSpeedTimesTimeWhateverTheFrameRate() {
        CameraController slow = new CameraController(new Camera(Vector3d.ZERO, Quaternion.IDENTITY, 60), SPEED, TURN);
        slow.apply(hold(Action.FORWARD, 1.0)); // one 1 s frame
        for (int i = 0; i < 100; i++) {        // a hundred 10 ms frames
            camera.apply(hold(Action.FORWARD, 0.01));
        }
        assertVector(new Vector3d(0, 0, SPEED), slow.camera().position(), EPS);
        assertVector(new Vector3d(0, 0, SPEED), camera.camera().position(), 1e-12);
    }

    @Test
    void shiftFliesFasterButTurnsAsUsual() {
        camera.apply(new InputFrame.Builder().hold(Action.FORWARD, 0.5).fast(true).build());
        assertVector(new Vector3d(0, 0, SPEED * 0.5 * CameraController.FAST_FACTOR), camera.camera().position(), EPS);
        camera.apply(new InputFrame.Builder().hold(Action.YAW_RIGHT, 1.5).fast(true).build());
        assertVector(new Vector3d(1, 0, 0), camera.camera().orientation().forward(), 1e-12);
    }

    @Test
    void wheelChangesTheSpeedWithinLimits() {
        camera.apply(new InputFrame.Builder().wheel(-2).build()); // two notches away from the user
        assertEquals(SPEED * 1.25 * 1.25, camera.speed(), 1e-12);
        camera.apply(hold(Action.FORWARD, 1));
        assertEquals(SPEED * 1.5625, camera.camera().position().z(), 1e-12);
        camera.apply(new InputFrame.Builder().wheel(1000).build());
        assertEquals(SPEED / CameraController.SPEED_FACTOR_LIMIT, camera.speed(), 1e-15);
        camera.apply(new InputFrame.Builder().wheel(-100000).build());
        assertEquals(SPEED * CameraController.SPEED_FACTOR_LIMIT, camera.speed(), 1e-9);
    }

    @Test
    void dragLooksWhereTheMouseGoes() {
        double pixels = 90 / CameraController.DRAG_DEGREES_PER_PIXEL;
        camera.apply(new InputFrame.Builder().drag(pixels, 0).build()); // drag right: turn right
        assertVector(new Vector3d(1, 0, 0), camera.camera().orientation().forward(), 1e-12);
        camera.apply(new InputFrame.Builder().drag(-pixels, 0).build()); // back left
        camera.apply(new InputFrame.Builder().drag(0, -pixels).build()); // drag up: look up
        assertVector(new Vector3d(0, 1, 0), camera.camera().orientation().forward(), 1e-12);
    }

    @Test
    void keysHeldTogetherCombine() {
        camera.apply(new InputFrame.Builder().hold(Action.FORWARD, 1).hold(Action.RIGHT, 1).hold(Action.UP, 0.5)
                .build());
        assertVector(new Vector3d(SPEED, SPEED * 0.5, SPEED), camera.camera().position(), EPS);

        CameraController turning = new CameraController(new Camera(Vector3d.ZERO, Quaternion.IDENTITY, 60), SPEED, TURN);
        turning.apply(new InputFrame.Builder().hold(Action.YAW_RIGHT, 0.5).hold(Action.PITCH_UP, 0.5).build());
        Vector3d f = turning.camera().orientation().forward();
        assertTrue(f.x() > 0.3 && f.y() > 0.3, "turns right and up at once: " + f);
        assertEquals(1, f.length(), 1e-12);
    }

    @Test
    void oppositeKeysCancel() {
        assertFalse(camera.apply(new InputFrame.Builder().hold(Action.FORWARD, 1).hold(Action.BACK, 1)
                .hold(Action.YAW_LEFT, 1).hold(Action.YAW_RIGHT, 1).build()));
        assertEquals(new Camera(Vector3d.ZERO, Quaternion.IDENTITY, 60), camera.camera());
        assertFalse(camera.apply(InputFrame.none()));
    }

    @Test
    void quaternionStaysUnitAfterAMillionSmallTurns() {
        Action[] turns = {Action.YAW_RIGHT, Action.PITCH_UP, Action.ROLL_LEFT, Action.PITCH_DOWN};
        double worst = 0;
        for (int i = 0; i < 1_000_000; i++) {
            InputFrame.Builder in = new InputFrame.Builder().hold(turns[i % turns.length], 1e-3 * (1 + i % 7));
            if (i % 3 == 0) {
                in.hold(Action.YAW_LEFT, 7e-4).drag(0.3, -0.2);
            }
            camera.apply(in.build());
            worst = Math.max(worst, Math.abs(camera.camera().orientation().norm() - 1));
        }
        assertTrue(worst <= 1e-12, "largest |norm - 1| " + worst);
        Quaternion q = camera.camera().orientation();
        assertEquals(0, q.right().dot(q.up()), 1e-12);
        assertEquals(0, q.up().dot(q.forward()), 1e-12);
        assertEquals(1, q.right().cross(q.up()).dot(q.forward()), 1e-12); // still a rotation, no reflection
    }

    @Test
    void noGimbalLockLookingStraightUp() {
        turn(Action.PITCH_UP, 90);
        Quaternion up = camera.camera().orientation();
        assertVector(new Vector3d(0, 1, 0), up.forward(), 1e-12);

        // yaw and roll are still different motions: yaw swings the view, roll spins it in place
        CameraController yawed = new CameraController(camera.camera(), SPEED, TURN);
        yawed.apply(hold(Action.YAW_RIGHT, 1.5));
        assertVector(new Vector3d(1, 0, 0), yawed.camera().orientation().forward(), 1e-12);
        CameraController rolled = new CameraController(camera.camera(), SPEED, TURN);
        rolled.apply(hold(Action.ROLL_RIGHT, 1.5));
        assertVector(new Vector3d(0, 1, 0), rolled.camera().orientation().forward(), 1e-12);
        assertVector(new Vector3d(1, 0, 0), rolled.camera().orientation().up(), 1e-12);

        // pitching on goes over the top: no clamp, no flip
        turn(Action.PITCH_UP, 90);
        assertVector(new Vector3d(0, 0, -1), camera.camera().orientation().forward(), 1e-12);
        assertVector(new Vector3d(0, -1, 0), camera.camera().orientation().up(), 1e-12);
    }

    @Test
    void resetTakesAPose() {
        Camera pose = Camera.lookAt(new Vector3d(1, 2, 3), new Vector3d(1, 2, 4), Vector3d.UNIT_Y, 45);
        camera.reset(pose);
        assertEquals(pose.position(), camera.camera().position());
        assertEquals(45, camera.camera().fovDegrees());
        assertVector(new Vector3d(0, 0, 1), camera.camera().orientation().forward(), 1e-15);
    }
}
