package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.math.Vector3d;
import glint.scene.Camera;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.function.Function;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every camera model ({@link CameraModel}'s permitted classes, found by reflection) against the interface's
 * contract, on seeded random cameras of its case: it is what {@link CameraModel#of} compiles its scene
 * cameras to; its rays are unit and leave its lens (the eye itself for a camera of one origin); and every
 * ray through a film point, whatever its lens point, passes through the one point of the plane in focus
 * that {@code imagePoint} maps back to that film point. A new camera model needs its entry in
 * {@link #CASES}; the test fails while a permitted class has none.
 */
class CameraModelContractTest {

    /** Per camera model: a scene camera that compiles to it. */
    private static final Map<Class<?>, Function<SplittableRandom, Camera>> CASES = Map.of(
            PinholeCamera.class, random -> randomCamera(random, 0),
            ThinLensCamera.class, random -> randomCamera(random, Math.exp(random.nextDouble(-7, 2))));

    /** Relative tolerance of a ray's point in focus: far above rounding (about 1e-15), far below a pixel. */
    private static final double RELATIVE = 1e-9;
    private static final int TRIALS = 300, LENS_POINTS = 9;

    /** The camera models scene cameras compile to: those {@link CameraModel#of} gives, each with its case. */
    static Stream<Class<?>> models() {
        return CASES.keySet().stream().sorted(java.util.Comparator.comparing(Class::getName));
    }

    /** A camera anywhere in a box of 100, looking anywhere, fov in [5, 150], focused 0.01 to 1000 ahead. */
    private static Camera randomCamera(SplittableRandom random, double aperture) {
        Vector3d eye = new Vector3d(random.nextDouble(-50, 50), random.nextDouble(-50, 50), random.nextDouble(-50, 50));
        double[] towards = RandomScenes.unitVector(random);
        Vector3d target = eye.add(new Vector3d(towards[0], towards[1], towards[2]));
        return Camera.lookAt(eye, target, Vector3d.UNIT_Y, random.nextDouble(5, 150))
                .withLens(aperture, Math.exp(random.nextDouble(-4.6, 6.9)));
    }

    /** Whatever a scene camera is (a pinhole, any lens), the model it compiles to has a case here. */
    @Test
    void everyCameraModelASceneCameraCompilesToHasACase() {
        SplittableRandom random = new SplittableRandom(60);
        for (int trial = 0; trial < TRIALS; trial++) {
            double aperture = trial % 3 == 0 ? 0 : Math.exp(random.nextDouble(-30, 30));
            Class<?> model = CameraModel.of(randomCamera(random, aperture)).getClass();
            assertTrue(CASES.containsKey(model), model + " has no case in CASES");
        }
        assertTrue(CASES.size() >= 2, "the pinhole and the thin lens at least");
    }

    @ParameterizedTest
    @MethodSource("models")
    void theSceneCameraOfItsCaseCompilesToIt(Class<?> model) {
        SplittableRandom random = new SplittableRandom(61);
        for (int trial = 0; trial < TRIALS; trial++) {
            assertEquals(model, CameraModel.of(CASES.get(model).apply(random)).getClass());
        }
    }

    @ParameterizedTest
    @MethodSource("models")
    void raysAreUnitAndLeaveTheLens(Class<?> model) {
        SplittableRandom random = new SplittableRandom(62);
        double[] o = new double[3], d = new double[3];
        for (int trial = 0; trial < TRIALS; trial++) {
            Camera scene = CASES.get(model).apply(random);
            CameraModel camera = CameraModel.of(scene);
            Vector3d eye = camera.eye(), forward = scene.orientation().forward();
            assertEquals(scene.position(), eye);
            int width = 1 + random.nextInt(900), height = 1 + random.nextInt(700);
            for (int k = 0; k < LENS_POINTS; k++) {
                ray(camera, random.nextDouble(0, width), random.nextDouble(0, height), lensU(k, random),
                        lensV(k, random), width, height, o, d);
                assertEquals(1, Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), 1e-14);
                Vector3d offset = new Vector3d(o[0], o[1], o[2]).sub(eye);
                if (camera.oneOrigin()) {
                    assertEquals(eye, new Vector3d(o[0], o[1], o[2]), "a camera of one origin: every ray leaves it");
                }
                // the origin's rounding, far from the world's origin: 1e-14 of the eye's distance
                double reach = scene.aperture() * (1 + 1e-12) + 1e-14 * eye.length();
                assertTrue(offset.length() <= reach, () -> "off the lens: " + offset + " of " + scene);
                assertEquals(0, offset.dot(forward), 1e-12 * (1 + eye.length()), "in the lens's plane");
            }
        }
    }

    @ParameterizedTest
    @MethodSource("models")
    void everyRayThroughAFilmPointMeetsThePointInFocusSeenThere(Class<?> model) {
        SplittableRandom random = new SplittableRandom(63);
        double[] o = new double[3], d = new double[3];
        for (int trial = 0; trial < TRIALS; trial++) {
            Camera scene = CASES.get(model).apply(random);
            CameraModel camera = CameraModel.of(scene);
            Vector3d eye = camera.eye(), forward = scene.orientation().forward();
            int width = 1 + random.nextInt(900), height = 1 + random.nextInt(700);
            double px = random.nextDouble(0, width), py = random.nextDouble(0, height);
            Vector3d first = null;
            for (int k = 0; k < LENS_POINTS; k++) {
                ray(camera, px, py, lensU(k, random), lensV(k, random), width, height, o, d);
                Vector3d origin = new Vector3d(o[0], o[1], o[2]), direction = new Vector3d(d[0], d[1], d[2]);
                // along the ray to the plane in focus: (p - eye) . forward = focus
                double t = (scene.focus() - origin.sub(eye).dot(forward)) / direction.dot(forward);
                Vector3d inFocus = origin.add(direction.scale(t));
                double reach = inFocus.sub(eye).length();
                if (first == null) {
                    first = inFocus;
                    CameraModel.ImagePoint seen = camera.imagePoint(inFocus, width, height).orElseThrow();
                    String where = "film point " + px + ", " + py + " of " + scene;
                    assertEquals(px, seen.px(), RELATIVE * Math.max(width, height), where);
                    assertEquals(py, seen.py(), RELATIVE * Math.max(width, height), where);
                } else {
                    assertEquals(0, inFocus.sub(first).length(), RELATIVE * reach,
                            "every lens point's ray meets the same point in focus, " + scene);
                }
            }
        }
    }

    /**
     * Light tracing's view of the camera: a point on a camera ray (film point and lens point given) is seen by
     * {@code sees} with the same lens numbers at that film point, from that lens point, with the ray's own
     * direction density as its importance.
     */
    @ParameterizedTest
    @MethodSource("models")
    void aPointOnACameraRayIsSeenAtItsFilmPointFromItsLensPoint(Class<?> model) {
        SplittableRandom random = new SplittableRandom(64);
        double[] o = new double[3], d = new double[3];
        CameraSight sight = new CameraSight();
        for (int trial = 0; trial < TRIALS; trial++) {
            Camera scene = CASES.get(model).apply(random);
            CameraModel camera = CameraModel.of(scene);
            int width = 1 + random.nextInt(900), height = 1 + random.nextInt(700);
            double px = random.nextDouble(0, width), py = random.nextDouble(0, height);
            double u = random.nextDouble(), v = random.nextDouble();
            ray(camera, px, py, u, v, width, height, o, d);
            double t = Math.exp(random.nextDouble(-3, 5));
            double qx = o[0] + t * d[0], qy = o[1] + t * d[1], qz = o[2] + t * d[2];
            String where = "film point " + px + ", " + py + " at " + t + " of " + scene;
            assertTrue(camera.sees(qx, qy, qz, u, v, width, height, sight), where);
            double pixels = 1e-7 * Math.max(width, height) * (1 + camera.eye().length() / t);
            assertEquals(px, sight.filmX, pixels, where);
            assertEquals(py, sight.filmY, pixels, where);
            assertEquals(o[0], sight.lensX, 1e-9 * (1 + camera.eye().length()), where);
            assertEquals(t, sight.distance, 1e-9 * (t + camera.eye().length()), where);
            assertEquals(-d[0], sight.towardX, 1e-6 * (1 + camera.eye().length() / t), where);
            double pdf = camera.directionPdf(o[0], o[1], o[2], d[0], d[1], d[2], width, height);
            assertEquals(pdf, sight.importance, 1e-6 * pdf, where);
            assertTrue(!camera.sees(o[0] - d[0], o[1] - d[1], o[2] - d[2], u, v, width, height, sight),
                    "behind the lens: " + where);
        }
    }

    /**
     * The direction density of the camera's rays is one over the whole sphere: its mean over directions
     * uniform on the sphere, times 4 pi, is 1 (from the lens centre and, for a lens, from a point off it).
     */
    @ParameterizedTest
    @MethodSource("models")
    void theDirectionDensityIntegratesToOne(Class<?> model) {
        SplittableRandom random = new SplittableRandom(65);
        for (int trial = 0; trial < 6; trial++) {
            Camera scene = CASES.get(model).apply(random);
            CameraModel camera = CameraModel.of(scene);
            int width = 40 + random.nextInt(600), height = 40 + random.nextInt(400);
            double[] o = new double[3], d = new double[3];
            ray(camera, width / 2.0, height / 2.0, random.nextDouble(), random.nextDouble(), width, height, o, d);
            int n = 2_000_000;
            double sum = 0, sum2 = 0;
            for (int i = 0; i < n; i++) {
                double[] w = RandomScenes.unitVector(random);
                double p = 4 * Math.PI * camera.directionPdf(o[0], o[1], o[2], w[0], w[1], w[2], width, height);
                sum += p;
                sum2 += p * p;
            }
            double mean = sum / n, error = Math.sqrt((sum2 / n - mean * mean) / n);
            assertEquals(1, mean, 5 * error + 1e-3, scene + " at " + width + " x " + height);
        }
    }

    /** The lens point's first number: the square's corners and centre, then random ones. */
    private static double lensU(int k, SplittableRandom random) {
        return k == 0 ? 0 : k == 1 ? 0.5 : k == 2 ? Math.nextDown(1.0) : random.nextDouble();
    }

    private static double lensV(int k, SplittableRandom random) {
        return k == 0 ? 0 : k == 1 ? 0.5 : k == 2 ? Math.nextDown(1.0) : random.nextDouble();
    }

    private static void ray(CameraModel camera, double px, double py, double u, double v, int width, int height,
                            double[] o, double[] d) {
        double[] ox = new double[1], oy = new double[1], oz = new double[1];
        double[] dx = new double[1], dy = new double[1], dz = new double[1];
        camera.ray(px, py, u, v, width, height, ox, oy, oz, dx, dy, dz, 0);
        o[0] = ox[0];
        o[1] = oy[0];
        o[2] = oz[0];
        d[0] = dx[0];
        d[1] = dy[0];
        d[2] = dz[0];
    }
}
