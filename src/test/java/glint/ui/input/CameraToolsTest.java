package glint.ui.input;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.input.InputException;
import glint.math.Vector3d;
import glint.render.PinholeCamera;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.scene.Camera;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import org.junit.jupiter.api.Test;

/** The modelling viewport's tools: orbit around a picked point, zoom, flying up along the world's up, key C. */
class CameraToolsTest {

    private static final double EPS = 1e-9;

    private static void assertVector(Vector3d expected, Vector3d actual, double tolerance) {
        assertEquals(0, expected.sub(actual).length(), tolerance, () -> "expected " + expected + ", got " + actual);
    }

    /** Where a point is seen: its direction from the eye in the camera's frame. */
    private static Vector3d seen(Camera c, Vector3d point) {
        Vector3d d = point.sub(c.position()).normalize();
        return new Vector3d(d.dot(c.orientation().right()), d.dot(c.orientation().up()), d.dot(c.orientation().forward()));
    }

    @Test
    void inALevelCameraRAndFFlyAlongTheWorldsUpWhateverThePitch() {
        Camera pitched = Camera.lookAt(Vector3d.ZERO, new Vector3d(0, -1, 1), Vector3d.UNIT_Y, 60);
        CameraController level = new CameraController(pitched, 2, 60);
        assertTrue(level.apply(new InputFrame.Builder().hold(Action.UP, 0.5).build()));
        assertVector(new Vector3d(0, 1, 0), level.camera().position(), EPS);
        CameraController free = new CameraController(pitched, 2, 60);
        free.setFreeFlight(true);
        free.apply(new InputFrame.Builder().hold(Action.UP, 0.5).build());
        assertVector(pitched.orientation().up(), free.camera().position(), EPS); // along its own up
    }

    /** A scene's view beyond the keys' range: zooming moves it toward the range, never jumps to its bound. */
    @Test
    void zoomMovesAFieldOfViewOutsideItsRangeTowardTheRangeNeverPastOrAway() {
        Camera wide = Camera.lookAt(Vector3d.ZERO, Vector3d.UNIT_Z, Vector3d.UNIT_Y, 170);
        CameraController c = new CameraController(wide, 2, 60);
        assertFalse(c.apply(new InputFrame.Builder().hold(Action.ZOOM_OUT, 0.1).build()), "X: no wider, not 150");
        assertEquals(170, c.camera().fovDegrees());
        assertTrue(c.apply(new InputFrame.Builder().hold(Action.ZOOM_IN, 0.1).build()));
        assertEquals(170 * Math.pow(2, -0.1), c.camera().fovDegrees(), EPS, "Z narrows it from where it is");
        Camera narrow = Camera.lookAt(Vector3d.ZERO, Vector3d.UNIT_Z, Vector3d.UNIT_Y, 0.5);
        CameraController n = new CameraController(narrow, 2, 60);
        assertFalse(n.apply(new InputFrame.Builder().hold(Action.ZOOM_IN, 0.1).build()), "Z: no narrower, not 1");
        assertEquals(0.5, n.camera().fovDegrees());
        assertTrue(n.apply(new InputFrame.Builder().hold(Action.ZOOM_OUT, 0.5).build()));
        assertEquals(0.5 * Math.sqrt(2), n.camera().fovDegrees(), EPS, "X widens it from where it is");
        n.apply(new InputFrame.Builder().hold(Action.ZOOM_OUT, 60).build());
        assertEquals(CameraController.MAX_FOV, n.camera().fovDegrees(), "and stops at the bound it moved toward");
    }

    @Test
    void zoomKeysHalveAndDoubleTheFieldOfViewEachSecondWithinBounds() {
        CameraController c = new CameraController(Camera.defaults(), 2, 60);
        assertTrue(c.apply(new InputFrame.Builder().hold(Action.ZOOM_IN, 1).build()));
        assertEquals(30, c.camera().fovDegrees(), EPS);
        c.apply(new InputFrame.Builder().hold(Action.ZOOM_OUT, 2).build());
        assertEquals(120, c.camera().fovDegrees(), EPS);
        c.apply(new InputFrame.Builder().hold(Action.ZOOM_OUT, 10).build());
        assertEquals(CameraController.MAX_FOV, c.camera().fovDegrees());
        assertFalse(c.apply(new InputFrame.Builder().hold(Action.ZOOM_OUT, 1).build()), "at the bound: no change");
        c.apply(new InputFrame.Builder().hold(Action.ZOOM_IN, 60).build());
        assertEquals(CameraController.MIN_FOV, c.camera().fovDegrees());
        assertEquals(Camera.defaults().position(), c.camera().position(), "zoom does not move the camera");
    }

    @Test
    void anOrbitKeepsThePivotWhereItIsSeenAndTheHorizonLevel() {
        Camera start = Camera.lookAt(new Vector3d(0, 2, -5), new Vector3d(0, 1, 0), Vector3d.UNIT_Y, 60);
        CameraController c = new CameraController(start, 2, 60);
        Vector3d pivot = new Vector3d(0.5, 0.7, 0.2);
        Vector3d seenBefore = seen(start, pivot);
        double distance = start.position().sub(pivot).length();
        c.orbitAround(pivot);
        assertTrue(c.apply(new InputFrame.Builder().orbit(150, -40).build()));
        Camera after = c.camera();
        assertVector(seenBefore, seen(after, pivot), 1e-9);
        assertEquals(distance, after.position().sub(pivot).length(), 1e-9);
        assertEquals(0, CameraController.roll(after.orientation()), 1e-12, "the horizon stays level");
        assertTrue(after.position().sub(start.position()).length() > 1, "it went round: " + after.position());
        assertTrue(after.position().y() < start.position().y(), "a drag up lowers the camera");
        assertTrue(after.position().x() < start.position().x(), "a drag right circles to the left");
    }

    @Test
    void anOrbitStopsAtThePitchBoundAsTurningDoes() {
        CameraController c = new CameraController(Camera.defaults(), 2, 60);
        c.orbitAround(new Vector3d(0, 1, 0));
        c.apply(new InputFrame.Builder().orbit(0, 5000).build()); // far down: the camera rises over the top
        double elevation = Math.toDegrees(Math.asin(-c.camera().orientation().forward().y()));
        assertEquals(90 - CameraController.PITCH_LIMIT_DEGREES, elevation, 1e-6);
        assertEquals(0, CameraController.roll(c.camera().orientation()), 1e-9);
    }

    @Test
    void thePivotIsThePointUnderThePixelOrAheadWhenTheRayMissesEverything() throws InputException {
        Scene scene = SceneLoader.parse("s.yaml", """
                camera: {position: [0, 1, -4], look_at: [0, 1, 0]}
                objects:
                  - {type: sphere, center: [0, 1, 0], radius: 1}
                """);
        RenderScene compiled = RenderScene.compile(scene, Config.defaults().renderSettings());
        Vector3d centre = OrbitPivot.pick(compiled, scene.camera(), 49.5, 39.5, 100, 80); // the middle of 100x80
        assertVector(new Vector3d(0, 1, -1), centre, 1e-9);
        Vector3d miss = OrbitPivot.pick(compiled, scene.camera(), 0, 0, 100, 80);
        assertVector(new Vector3d(0, 1, -4 + CameraController.ORBIT_MISS_DISTANCE), miss, 1e-9);
    }

    @Test
    void thePivotLiesOnTheCamerasRayThroughThePixelsCentre() throws InputException {
        Scene scene = SceneLoader.parse("s.yaml", """
                camera: {position: [0.3, 1, -4], look_at: [1, 1.5, 0], fov: 70}
                objects:
                  - {type: plane, point: [0, 0, 10], normal: [0, 0, -1]}
                """);
        RenderScene compiled = RenderScene.compile(scene, Config.defaults().renderSettings());
        PinholeCamera camera = new PinholeCamera(scene.camera());
        java.util.SplittableRandom random = new java.util.SplittableRandom(46);
        for (int trial = 0; trial < 50; trial++) {
            double x = random.nextDouble(0, 160), y = random.nextDouble(0, 90);
            Vector3d pivot = OrbitPivot.pick(compiled, scene.camera(), x, y, 160, 90);
            assertEquals(10, pivot.z(), 1e-9, "on the wall");
            assertVector(camera.direction(x + 0.5, y + 0.5, 160, 90), pivot.sub(camera.eye()).normalize(), 1e-12);
        }
    }
}
