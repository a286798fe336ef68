package glint.ui.input;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.math.Quaternion;
import glint.math.Vector3d;
import glint.scene.Camera;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The camera flies in its own frame, by elapsed time, and its quaternion stays unit. A level camera turns
 * about the world's up axis and keeps its horizon; in free flight it turns about its own axes.
 */
class CameraControllerTest {

    private static final double SPEED = 2;       // units per second
    private static final double TURN = 60;       // degrees per second
    private static final double EPS = 1e-12;

    private final CameraController camera =
            new CameraController(new Camera(Vector3d.ZERO, Quaternion.IDENTITY, 60), SPEED, TURN);

    /** The seed's free flight: every turn about the camera's own axes, pitch unbounded. */
    private static CameraController free() {
        CameraController c = new CameraController(new Camera(Vector3d.ZERO, Quaternion.IDENTITY, 60), SPEED, TURN);
        c.setFreeFlight(true);
        return c;
    }

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
        turn(camera, action, degrees);
    }

    private static void turn(CameraController c, Action action, double degrees) {
        assertTrue(c.apply(hold(action, degrees / TURN)));
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
    void inFreeFlightAfterLookingUpForwardIsWorldUp() {
        CameraController c = free();
        turn(c, Action.PITCH_UP, 90);
        c.apply(hold(Action.FORWARD, 1));
        assertVector(new Vector3d(0, SPEED, 0), c.camera().position(), 1e-12);
    }

    @Test
    void afterRollingLeftUpIsWorldLeftInFreeFlightAndStillWorldUpInALevelCamera() {
        CameraController plane = free();
        turn(plane, Action.ROLL_LEFT, 90);
        assertVector(new Vector3d(0, 0, 1), plane.camera().orientation().forward(), 1e-12); // roll keeps the view
        plane.apply(hold(Action.UP, 1));
        assertVector(new Vector3d(-SPEED, 0, 0), plane.camera().position(), 1e-12);
        turn(Action.ROLL_LEFT, 90);
        camera.apply(hold(Action.UP, 1));
        assertVector(new Vector3d(0, SPEED, 0), camera.camera().position(), 1e-12);
    }

    @ParameterizedTest(name = "{0} turns forward to ({1}, {2}, {3})")
    @CsvSource({
        "YAW_RIGHT, 1, 0, 0", "YAW_LEFT, -1, 0, 0", "PITCH_UP, 0, 1, 0", "PITCH_DOWN, 0, -1, 0"})
    void inFreeFlightArrowsTurnByTurnSpeedTimesTime(Action key, double x, double y, double z) {
        CameraController c = free();
        c.apply(hold(key, 1.5)); // 60 degrees a second for 1.5 s: a right angle
        assertVector(new Vector3d(x, y, z), c.camera().orientation().forward(), 1e-12);
    }

    @ParameterizedTest(name = "{0} turns forward to ({1}, {2}, {3})")
    @CsvSource({
        "YAW_RIGHT, 0.5, 0, 0.8660254037844386", "YAW_LEFT, -0.5, 0, 0.8660254037844386",
        "PITCH_UP, 0, 0.5, 0.8660254037844386", "PITCH_DOWN, 0, -0.5, 0.8660254037844386"})
    void arrowsTurnByTurnSpeedTimesTime(Action key, double x, double y, double z) {
        camera.apply(hold(key, 0.5)); // 60 degrees a second for 0.5 s: 30 degrees
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
        camera.apply(new InputFrame.Builder().drag(0, -pixels / 3).build()); // drag up: look up
        assertVector(new Vector3d(0, 0.5, Math.sqrt(0.75)), camera.camera().orientation().forward(), 1e-12);
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
    void inFreeFlightNoGimbalLockLookingStraightUp() {
        CameraController camera = free();
        turn(camera, Action.PITCH_UP, 90);
        Quaternion up = camera.camera().orientation();
        assertVector(new Vector3d(0, 1, 0), up.forward(), 1e-12);

        // yaw and roll are still different motions: yaw swings the view, roll spins it in place
        CameraController yawed = new CameraController(camera.camera(), SPEED, TURN);
        yawed.setFreeFlight(true);
        yawed.apply(hold(Action.YAW_RIGHT, 1.5));
        assertVector(new Vector3d(1, 0, 0), yawed.camera().orientation().forward(), 1e-12);
        CameraController rolled = new CameraController(camera.camera(), SPEED, TURN);
        rolled.setFreeFlight(true);
        rolled.apply(hold(Action.ROLL_RIGHT, 1.5));
        assertVector(new Vector3d(0, 1, 0), rolled.camera().orientation().forward(), 1e-12);
        assertVector(new Vector3d(1, 0, 0), rolled.camera().orientation().up(), 1e-12);

        // pitching on goes over the top: no clamp, no flip
        turn(camera, Action.PITCH_UP, 90);
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

    // ---- the level camera ----

    /** The default scene's camera: it looks slightly down. */
    private static Camera lookingDown() {
        return Camera.lookAt(new Vector3d(0, 1.6, -6), new Vector3d(0, 0.9, 0), Vector3d.UNIT_Y, 60);
    }

    private static double elevationDegrees(CameraController c) {
        return Math.toDegrees(Math.asin(c.camera().orientation().forward().y()));
    }

    @Test
    void rightDownLeftUpComesBackLevelToTheStart() {
        CameraController c = new CameraController(lookingDown(), SPEED, TURN);
        Quaternion start = c.camera().orientation();
        for (Action a : new Action[] {Action.YAW_RIGHT, Action.PITCH_DOWN, Action.YAW_LEFT, Action.PITCH_UP}) {
            turn(c, a, 40);
            assertEquals(0, c.roll(), 1e-15, "roll after " + a);
        }
        assertVector(start.forward(), c.camera().orientation().forward(), 1e-14);
        assertVector(start.up(), c.camera().orientation().up(), 1e-14);
    }

    @Test
    void anySequenceOfYawAndPitchKeepsRollBelowANanoradian() {
        java.util.Random random = new java.util.Random(25);
        Action[] turns = {Action.YAW_LEFT, Action.YAW_RIGHT, Action.PITCH_UP, Action.PITCH_DOWN};
        CameraController c = new CameraController(lookingDown(), SPEED, TURN);
        double worstRoll = 0;
        double highest = 0;
        for (int i = 0; i < 200_000; i++) {
            InputFrame.Builder in = new InputFrame.Builder()
                    .hold(turns[random.nextInt(4)], random.nextDouble() * 2) // up to 120 degrees
                    .hold(turns[random.nextInt(4)], random.nextDouble() * 0.05);
            if (random.nextInt(3) == 0) {
                in.drag(random.nextGaussian() * 200, random.nextGaussian() * 200);
            }
            c.apply(in.build());
            worstRoll = Math.max(worstRoll, Math.abs(c.roll()));
            highest = Math.max(highest, Math.abs(elevationDegrees(c)));
        }
        assertTrue(worstRoll < 1e-9, "largest roll " + worstRoll + " rad");
        assertTrue(highest <= 90 - CameraController.PITCH_LIMIT_DEGREES + 1e-9, "steepest view " + highest);
        assertEquals(1, c.camera().orientation().norm(), 1e-12);
    }

    @ParameterizedTest(name = "{0} stops short of straight up or down")
    @CsvSource({"PITCH_UP, 1", "PITCH_DOWN, -1"})
    void pitchIsBounded(Action key, double sign) {
        CameraController c = new CameraController(lookingDown(), SPEED, TURN);
        c.apply(hold(key, 10)); // 600 degrees: it would go over the top three times
        assertEquals(sign * (90 - CameraController.PITCH_LIMIT_DEGREES), elevationDegrees(c), 1e-9);
        assertFalse(c.apply(hold(key, 1)), "at the bound, turning on does nothing");
        assertTrue(c.camera().orientation().up().y() > 0, "the camera is not upside down");
        c.apply(hold(key == Action.PITCH_UP ? Action.PITCH_DOWN : Action.PITCH_UP, 89.0 / TURN)); // back 89
        assertEquals(0, elevationDegrees(c), 1e-9);
    }

    @Test
    void rolledThePitchStopsWhereTheViewIsHighest() {
        CameraController c = new CameraController(lookingDown(), SPEED, TURN);
        turn(c, Action.ROLL_LEFT, 30);
        Quaternion q = c.camera().orientation();
        // pitching about the tilted right axis, forward's height is at most |(f.y, u.y)|
        double highest = Math.hypot(q.forward().y(), q.up().y());
        c.apply(hold(Action.PITCH_UP, 10));
        assertEquals(highest, c.camera().orientation().forward().y(), 1e-12);
        assertFalse(c.apply(hold(Action.PITCH_UP, 1)), "it does not turn over");
        c.apply(hold(Action.PITCH_DOWN, 10));
        assertEquals(-highest, c.camera().orientation().forward().y(), 1e-12);
    }

    @Test
    void yawLooksAroundTheWorldsUpAxisWhateverThePitch() {
        CameraController c = new CameraController(lookingDown(), SPEED, TURN);
        turn(c, Action.PITCH_UP, 60);
        double elevation = elevationDegrees(c);
        turn(c, Action.YAW_RIGHT, 90);
        assertEquals(elevation, elevationDegrees(c), 1e-12); // about the world's up: the height stays
        assertEquals(0, c.roll(), 1e-15);
    }

    @Test
    void onlyRollTiltsTheHorizonAndLevelTakesItOut() {
        CameraController c = new CameraController(lookingDown(), SPEED, TURN);
        turn(c, Action.ROLL_LEFT, 20);
        assertEquals(Math.toRadians(20), c.roll(), 1e-12);
        turn(c, Action.YAW_RIGHT, 50);
        turn(c, Action.PITCH_UP, 30);
        Vector3d forward = c.camera().orientation().forward();
        Vector3d position = c.camera().position();
        assertTrue(c.level());
        assertEquals(0, c.roll(), 1e-12);
        assertTrue(c.camera().orientation().up().y() > 0);
        assertVector(forward, c.camera().orientation().forward(), 1e-12); // it looks where it looked
        assertEquals(position, c.camera().position());
        assertFalse(c.level(), "a level camera stays as it is");
    }

    @Test
    void levelFromStraightUpInFreeFlightKeepsTheHeading() {
        CameraController c = free();
        turn(c, Action.YAW_RIGHT, 90); // heading +x
        turn(c, Action.PITCH_UP, 90);  // straight up, the camera's top towards -x
        assertTrue(c.level());
        assertEquals(0, c.roll(), 1e-12);
        assertEquals(90 - CameraController.PITCH_LIMIT_DEGREES, elevationDegrees(c), 1e-9);
        assertTrue(c.camera().orientation().forward().x() > 0, "still heading +x");
    }

    @Test
    void flightStopsAt1e150FromTheOriginWhereTheCameraCanStillBeWritten() throws Exception {
        // move_speed 1e308, the largest a config takes: a second forward would be 1e308, two infinity
        CameraController fast = new CameraController(new Camera(Vector3d.ZERO, Quaternion.IDENTITY, 60), 1e308, TURN);
        assertFalse(fast.apply(hold(Action.FORWARD, 1)), "no move beyond 1e150, the longest length of a scene");
        assertFalse(fast.apply(new InputFrame.Builder().hold(Action.FORWARD, 1).hold(Action.RIGHT, 1).build()));
        assertEquals(Vector3d.ZERO, fast.camera().position());
        CameraController far = new CameraController(new Camera(Vector3d.ZERO, Quaternion.IDENTITY, 60), 1e149, TURN);
        assertTrue(far.apply(hold(Action.FORWARD, 10)));
        assertEquals(new Vector3d(0, 0, 1e150), far.camera().position());
        assertTrue(far.apply(hold(Action.BACK, 1)), "back towards the origin");
        assertFalse(far.apply(hold(Action.FORWARD, 2)));
        assertEquals(new Vector3d(0, 0, 9e149), far.camera().position());
    }

    /** A scene may open its lens wider than the widest step, its focus distance: widening keeps it, narrowing steps down. */
    @Test
    void wideningALensOpenedPastTheWidestStepKeepsIt() {
        Camera wide = new Camera(Vector3d.ZERO, Quaternion.IDENTITY, 60).withLens(0.5, 0.3);
        CameraController c = new CameraController(wide, SPEED, TURN);
        assertFalse(c.stepAperture(1));
        assertEquals(0.5, c.camera().aperture());
        assertTrue(c.stepAperture(-1));
        assertEquals(0.5 / Math.sqrt(2), c.camera().aperture(), 1e-15);
    }

    /** turn_speed takes any positive number: 1e300 degrees a second turns the camera somewhere, never to NaN. */
    @Test
    void aTurnSpeedOf1e300KeepsTheCameraAUnitQuaternionInFreeFlightAndLevel() {
        for (boolean freeFlight : new boolean[] {true, false}) {
            CameraController c = new CameraController(new Camera(Vector3d.ZERO, Quaternion.IDENTITY, 60), SPEED, 1e300);
            c.setFreeFlight(freeFlight);
            for (Action key : new Action[] {Action.YAW_RIGHT, Action.PITCH_UP, Action.ROLL_LEFT}) {
                c.apply(hold(key, 1.0 / 60));
                c.apply(new InputFrame.Builder().hold(Action.YAW_LEFT, 0.02).hold(Action.PITCH_DOWN, 0.03)
                        .hold(Action.ROLL_RIGHT, 0.01).build());
                Quaternion q = c.camera().orientation();
                assertEquals(1, q.norm(), 1e-12, () -> "free flight " + freeFlight + ", after " + key + ": " + q);
            }
        }
        CameraController largest = free();
        largest.setSpeeds(SPEED, Double.MAX_VALUE);
        largest.apply(new InputFrame.Builder().hold(Action.YAW_RIGHT, 100).hold(Action.PITCH_UP, 100).build());
        assertEquals(1, largest.camera().orientation().norm(), 1e-12, "the largest double, held 100 s");
    }
}
