package glint.ui.capture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.input.InputException;
import glint.math.Quaternion;
import glint.math.Vector3d;
import glint.scene.Camera;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** Key C's camera block and views item, read back by the scene loader, are the camera they were written from. */
class CameraBlockTest {

    private static void assertNear(Vector3d expected, Vector3d actual, double tolerance, String what) {
        assertEquals(0, expected.sub(actual).length(), tolerance, () -> what + ": " + expected + " vs " + actual);
    }

    @Test
    void anyCameraRoundTripsThroughTheSceneLoader() throws InputException {
        Random random = new Random(7);
        for (int i = 0; i < 2000; i++) {
            Vector3d position = new Vector3d(random.nextGaussian() * 50, random.nextGaussian() * 50,
                    random.nextGaussian() * 50);
            Quaternion q = new Quaternion(random.nextGaussian(), random.nextGaussian(), random.nextGaussian(),
                    random.nextGaussian()).normalize(); // any orientation, rolled too
            Camera camera = new Camera(position, q, 1 + random.nextDouble() * 150);
            String block = CameraBlock.yaml(camera);
            Camera read = SceneLoader.parse("pasted.yaml", block).camera();
            // six decimals: the position to within 5e-7 a coordinate, the directions to within about 1e-6
            assertNear(camera.position(), read.position(), 1e-6, "position");
            assertNear(q.forward(), read.orientation().forward(), 2e-6, "forward");
            assertNear(q.up(), read.orientation().up(), 2e-6, "up");
            assertEquals(camera.fovDegrees(), read.fovDegrees(), 5e-7);
        }
    }

    @Test
    void aLensRoundTripsThroughTheSceneLoaderAndAPinholeKeepsItsFourKeys() throws InputException {
        Random random = new Random(8);
        for (int i = 0; i < 500; i++) {
            Vector3d position = new Vector3d(random.nextGaussian() * 50, random.nextGaussian() * 50,
                    random.nextGaussian() * 50);
            Quaternion q = new Quaternion(random.nextGaussian(), random.nextGaussian(), random.nextGaussian(),
                    random.nextGaussian()).normalize();
            double aperture = Math.exp(random.nextDouble() * 20 - 14), focus = Math.exp(random.nextDouble() * 16 - 8);
            Camera camera = new Camera(position, q, 1 + random.nextDouble() * 150, aperture, focus);
            for (String printed : new String[] {CameraBlock.yaml(camera), CameraBlock.blocks(camera)}) {
                Scene read = SceneLoader.parse("pasted.yaml", printed);
                for (Camera c : printed.contains("views:") ? new Camera[] {read.camera(), read.views().get(0).camera()}
                        : new Camera[] {read.camera()}) {
                    // six decimals above 1e-3, the shortest decimal that reads back below it
                    assertEquals(aperture, c.aperture(), aperture < 1e-3 ? 0 : 5e-7, printed);
                    assertEquals(focus, c.focus(), focus < 1e-3 ? 0 : 5e-7, printed);
                    assertNear(q.forward(), c.orientation().forward(), 2e-6, "forward");
                }
            }
        }
        Camera pinhole = Camera.lookAt(new Vector3d(0, 1.6, -6), new Vector3d(0, 1.6, 0), Vector3d.UNIT_Y, 60);
        assertEquals(0, SceneLoader.parse("pasted.yaml", CameraBlock.blocks(pinhole)).camera().aperture());
        assertTrue(!CameraBlock.blocks(pinhole).contains("aperture"), "a pinhole's block is as it was");
        assertEquals("""
                camera:
                  position: [0, 1.6, -6]
                  look_at: [0, 1.6, -5]
                  up: [0, 1, 0]
                  fov: 60
                  aperture: 0.05
                  focus: 6
                views:
                  - {position: [0, 1.6, -6], look_at: [0, 1.6, -5], up: [0, 1, 0], fov: 60, aperture: 0.05, focus: 6}
                """, CameraBlock.blocks(pinhole.withLens(0.05, 6)));
    }

    @Test
    void theBlockIsFourKeysUnderCamera() {
        Camera camera = Camera.lookAt(new Vector3d(0, 1.6, -6), new Vector3d(0, 1.6, 0), Vector3d.UNIT_Y, 60);
        assertEquals("""
                camera:
                  position: [0, 1.6, -6]
                  look_at: [0, 1.6, -5]
                  up: [0, 1, 0]
                  fov: 60
                """, CameraBlock.yaml(camera));
    }

    @Test
    void numbersKeepSixDecimalsWithoutTrailingZerosOrMinusZero() {
        assertEquals("0", CameraBlock.number(-0.0));
        assertEquals("0", CameraBlock.number(-1e-9));
        assertEquals("2", CameraBlock.number(2.0));
        assertEquals("0.123457", CameraBlock.number(0.1234567));
        assertEquals("-1250.5", CameraBlock.number(-1250.5));
        assertEquals("100000000", CameraBlock.number(1e8));
    }

    @Test
    void aCameraOfATinyOrAHugeSceneRoundTripsItsNumbersWhole() throws InputException {
        // six decimals would print 5e-20 as 0, and one unit ahead of 1e20 is 1e20 itself (look_at = position)
        for (double scale : new double[] {5e-20, 1e-140, 1e20, 3e149}) {
            Camera camera = Camera.lookAt(new Vector3d(0, scale, -scale), new Vector3d(0, 0, scale), Vector3d.UNIT_Y, 60);
            String block = CameraBlock.yaml(camera);
            Camera read = SceneLoader.parse("pasted.yaml", block).camera();
            assertEquals(camera.position(), read.position(), block);
            assertNear(camera.orientation().forward(), read.orientation().forward(), 2e-6, "forward of " + block);
            String views = CameraBlock.blocks(camera);
            assertEquals(camera.position(), SceneLoader.parse("views.yaml", views).views().get(0).camera().position());
        }
        // looking along (0, -5e-20, 1e-19), normalised: one unit ahead of a position of 1e-20 is that direction
        assertEquals("""
                camera:
                  position: [0, 5.0E-20, -5.0E-20]
                  look_at: [0, -0.447214, 0.894427]
                  up: [0, 0.894427, 0.447214]
                  fov: 60
                """, CameraBlock.yaml(Camera.lookAt(new Vector3d(0, 5e-20, -5e-20), new Vector3d(0, 0, 5e-20),
                Vector3d.UNIT_Y, 60)));
    }

    @Test
    void keyCPrintsACameraBlockAndAViewsItemThatReadBackAsTheSameCamera() throws InputException {
        Camera camera = Camera.lookAt(new Vector3d(0.1234567, 1, -3), new Vector3d(0.5, 0.9, 0), Vector3d.UNIT_Y, 47.5);
        String printed = CameraBlock.blocks(camera);
        Scene both = SceneLoader.parse("pasted.yaml", printed);
        assertEquals(CameraBlock.asPrinted(camera), both.camera());
        assertEquals(both.camera(), both.views().get(0).camera(), printed);
        assertTrue(printed.contains("\nviews:\n  - {position: [0.123457, 1, -3], look_at: ["), printed);
    }

    /** Flight stops 1e150 from the origin, a scene's longest length: key C's block of a camera there reads back. */
    @Test
    void aCameraAsFarOutAsFlightGoesReadsBack() throws InputException {
        Camera far = new Camera(new Vector3d(0, 0, 9e149), Quaternion.IDENTITY, 60);
        String block = CameraBlock.yaml(far);
        assertEquals(far.position(), SceneLoader.parse("c.yaml", block).camera().position(), block);
    }

    /** Any fov a scene may have, 0 and 180 excluded, prints as a number the scene reader takes and reads back as it. */
    @Test
    void aFieldOfViewNearZeroOrNear180PrintsAsANumberThatReadsBack() throws InputException {
        for (double fov : new double[] {179.9999999, 1e-7, 179.9999996, 4e-7, 0.0012345678, Math.nextDown(180.0),
                Double.MIN_VALUE}) {
            Camera camera = Camera.lookAt(Vector3d.ZERO, Vector3d.UNIT_Z, Vector3d.UNIT_Y, fov);
            Scene read = SceneLoader.parse("pasted.yaml", CameraBlock.blocks(camera));
            assertEquals(fov, read.camera().fovDegrees(), "the camera block of fov " + fov);
            assertEquals(fov, read.views().get(0).camera().fovDegrees(), "the views item of fov " + fov);
        }
        assertTrue(CameraBlock.yaml(Camera.lookAt(Vector3d.ZERO, Vector3d.UNIT_Z, Vector3d.UNIT_Y, 179.9999999))
                .contains("  fov: 179.9999999\n"));
        assertTrue(CameraBlock.yaml(Camera.lookAt(Vector3d.ZERO, Vector3d.UNIT_Z, Vector3d.UNIT_Y, 1e-7))
                .contains("  fov: 1.0E-7\n"));
        assertTrue(CameraBlock.yaml(Camera.lookAt(Vector3d.ZERO, Vector3d.UNIT_Z, Vector3d.UNIT_Y, 42.4264068712))
                .contains("  fov: 42.426407\n"), "six decimals where they keep it");
    }
}
