package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import glint.math.Vector3d;
import glint.scene.Camera;
import java.util.HashSet;
import java.util.Set;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The thin lens: at aperture 0 its rays are the pinhole's; its lens points are stratified over a pixel's
 * samples and a function of (pixel, frame, sample) alone; the square maps onto the disc by equal areas;
 * and rendered, a point in focus stays as sharp as the pinhole draws it while an edge at infinity blurs
 * by the circle of confusion worked out by hand.
 */
class ThinLensCameraTest {

    private static Camera randomCamera(SplittableRandom random) {
        Vector3d eye = new Vector3d(random.nextDouble(-50, 50), random.nextDouble(-50, 50), random.nextDouble(-50, 50));
        double[] towards = RandomScenes.unitVector(random);
        Vector3d target = eye.add(new Vector3d(towards[0], towards[1], towards[2]));
        return Camera.lookAt(eye, target, Vector3d.UNIT_Y, random.nextDouble(5, 150))
                .withLens(0, Math.exp(random.nextDouble(-4.6, 6.9)));
    }

    @Test
    void atApertureZeroItsRaysAreThePinholes() {
        SplittableRandom random = new SplittableRandom(71);
        double[] ox = new double[1], oy = new double[1], oz = new double[1];
        double[] dx = new double[1], dy = new double[1], dz = new double[1];
        for (int trial = 0; trial < 500; trial++) {
            Camera camera = randomCamera(random);
            assertTrue(CameraModel.of(camera) instanceof PinholeCamera, "aperture 0 compiles to the pinhole");
            ThinLensCamera lens = new ThinLensCamera(camera);
            PinholeCamera pinhole = new PinholeCamera(camera);
            int width = 1 + random.nextInt(900), height = 1 + random.nextInt(700);
            double px = random.nextDouble(0, width), py = random.nextDouble(0, height);
            lens.ray(px, py, random.nextDouble(), random.nextDouble(), width, height, ox, oy, oz, dx, dy, dz, 0);
            assertEquals(pinhole.eye(), new Vector3d(ox[0], oy[0], oz[0]));
            Vector3d d = pinhole.direction(px, py, width, height);
            assertEquals(0, d.sub(new Vector3d(dx[0], dy[0], dz[0])).length(), 1e-15, camera::toString);
        }
    }

    @Test
    void theConcentricMapTakesEqualAreasOfTheSquareToEqualAreasOfTheDisc() {
        int side = 64;
        int inner = 0, outside = 0;
        int[] octants = new int[8];
        for (int i = 0; i < side; i++) {
            for (int j = 0; j < side; j++) {
                double a = (2 * i + 1.0) / side - 1, b = (2 * j + 1.0) / side - 1; // cell centres
                double r = ThinLensCamera.discRadius(a, b), angle = ThinLensCamera.discAngle(a, b);
                double x = r * Math.cos(angle), y = r * Math.sin(angle);
                double radius = Math.hypot(x, y);
                outside += radius > 1 ? 1 : 0;
                inner += radius < 0.5 ? 1 : 0;
                octants[(int) Math.floor((Math.atan2(y, x) + Math.PI) / (Math.PI / 4)) % 8]++;
            }
        }
        assertEquals(0, outside);
        assertEquals(side * side / 4, inner, "the disc of radius 1/2 holds a quarter of the area");
        for (int count : octants) {
            // the cell centres on the square's diagonals fall either side of an eighth's edge by rounding
            assertEquals(side * side / 8, count, side / 2.0, "each eighth of the disc an eighth of the square");
        }
        assertEquals(0, ThinLensCamera.discRadius(0, 0));
        assertEquals(0, ThinLensCamera.discAngle(0, 0));
    }

    /** One lens point in each cell of a pixel's grid; another pixel, frame or the film's cells shuffle them apart. */
    @Test
    void lensPointsAreStratifiedOverAPixelsSamplesAndDeterministic() {
        PathSamples lens = new PathSamples();
        int sameAsFilm = 0, pixels = 200;
        for (int side : new int[] {1, 2, 3, 4, 8, 16}) {
            int samples = side * side;
            for (int pixel = 0; pixel < pixels; pixel++) {
                Set<Integer> cells = new HashSet<>();
                boolean followsFilm = true;
                for (int sample = 0; sample < samples; sample++) {
                    lens.begin(pixel * 7919, pixel % 3, sample, samples);
                    lens.pair(PathSamples.LENS);
                    double u = lens.u1, v = lens.u2;
                    assertTrue(u >= 0 && u < 1 && v >= 0 && v < 1);
                    int cell = (int) (v * side) * side + (int) (u * side);
                    assertTrue(cells.add(cell), "cell " + cell + " twice in pixel " + pixel);
                    followsFilm &= cell == sample; // the film's sample s lies in cell s
                    lens.begin(pixel * 7919, pixel % 3, sample, samples); // again: the same numbers
                    lens.pair(PathSamples.LENS);
                    assertEquals(u, lens.u1);
                    assertEquals(v, lens.u2);
                }
                assertEquals(samples, cells.size());
                sameAsFilm += side >= 3 && followsFilm ? 1 : 0;
            }
        }
        assertTrue(sameAsFilm <= 2, "the lens's cells follow the film's in " + sameAsFilm + " pixels");
    }

    // ---------------------------------------------------------------- rendered: in focus and out of it

    private static final int SIZE = 64, SAMPLES = 64;
    private static final double FOV = 40;

    /** The image of a black ball before a white sky, through a lens of {@code aperture} focused at {@code focus}. */
    private static FrameBuffer ball(double depth, double aperture, double focus) {
        String yaml = "camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: " + FOV + ", aperture: " + aperture
                + ", focus: " + focus + "}\n"
                + "background: [1, 1, 1]\nambient: [0, 0, 0]\n"
                + "objects:\n  - {type: sphere, center: [0.05, 0.02, " + depth + "], radius: " + (0.08 * depth)
                + ", material: {type: matte, color: [0, 0, 0]}}\n";
        return Renders.render(Renders.scene(yaml), SIZE, SIZE, SAMPLES, 2, Shading.COOK_TORRANCE, 2, 3);
    }

    /**
     * A ball whose outline lies on the plane in focus renders as the pinhole renders it (the same film
     * samples; what differs is the lens's blur of a depth 0.2% off the plane, well under a hundredth of a
     * pixel, and the sampling); the same lens focused elsewhere does not.
     */
    @Test
    void aBallInFocusIsAsSharpAsThePinholeDrawsIt() {
        double depth = 5; // the outline's depth: about depth - radius^2 / depth, 0.3% nearer
        FrameBuffer pinhole = ball(depth, 0, 1), sharp = ball(depth, 0.2, depth * (1 - 0.0064)),
                blurred = ball(depth, 0.2, depth / 2);
        double worstSharp = 0, worstBlurred = 0;
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                worstSharp = Math.max(worstSharp, Math.abs(sharp.get(x, y, 0) - pinhole.get(x, y, 0)));
                worstBlurred = Math.max(worstBlurred, Math.abs(blurred.get(x, y, 0) - pinhole.get(x, y, 0)));
            }
        }
        // measured: 1/64 in focus (one film sample of 64 on the other side of the outline), 0.47 out of
        // focus (the outline smeared over a circle of confusion 7 pixels across)
        assertTrue(worstSharp < 0.05, "in focus, off the pinhole's image by " + worstSharp);
        assertTrue(worstBlurred > 0.3, "out of focus, off it by only " + worstBlurred);
    }

    /**
     * The horizon of a black floor under a white sky is an edge at infinity. A lens point l (its height
     * l_y over the lens centre) sees the floor through screen height s_y (s_y = 0 at the horizon) exactly
     * when focus s_y < l_y, so a row of the image is the sky's white over the fraction of the lens disc
     * below focus s_y: the thin lens's blur of an edge at infinity, aperture / focus on the screen either
     * side. Each row's mean, against that fraction averaged over the row's screen heights.
     */
    @Test
    void anEdgeAtInfinityBlursByTheCircleOfConfusion() {
        double aperture = 0.2, focus = 2;
        String yaml = "camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: " + FOV + ", aperture: " + aperture
                + ", focus: " + focus + "}\n"
                + "background: [1, 1, 1]\nambient: [0, 0, 0]\n"
                + "objects:\n  - {type: plane, point: [0, -1, 0], normal: [0, 1, 0], material: {type: matte,"
                + " color: [0, 0, 0]}}\n";
        FrameBuffer image = Renders.render(Renders.scene(yaml), SIZE, SIZE, SAMPLES, 2, Shading.COOK_TORRANCE, 2, 3);
        double perPixel = 2 * Math.tan(Math.toRadians(FOV) / 2) / SIZE; // screen units a pixel, either way
        double blurPixels = aperture / focus / perPixel; // the blur's half-height in pixels: 4.4
        for (int y = 0; y < SIZE; y++) {
            double mean = 0;
            for (int x = 0; x < SIZE; x++) {
                mean += image.get(x, y, 1) / SIZE;
            }
            double expected = 0;
            int steps = 1000;
            for (int k = 0; k < steps; k++) { // the row's screen heights, from its top edge down
                double sy = (SIZE / 2.0 - (y + (k + 0.5) / steps)) * perPixel;
                expected += belowOnDisc(focus * sy / aperture) / steps;
            }
            assertEquals(expected, mean, 0.02, "row " + y);
            double fromHorizon = Math.abs(y + 0.5 - SIZE / 2.0); // the row's centre, in pixels
            if (fromHorizon > blurPixels + 0.5) { // wholly outside the blur: all sky or all floor
                assertEquals(y < SIZE / 2 ? 1 : 0, mean, 0, "row " + y + " outside the blur");
            } else if (fromHorizon < blurPixels - 1) {
                assertTrue(mean > 0.01 && mean < 0.99, "row " + y + " inside the blur: " + mean);
            }
        }
    }

    /** The fraction of the unit disc below height t. */
    private static double belowOnDisc(double t) {
        if (t <= -1) {
            return 0;
        }
        if (t >= 1) {
            return 1;
        }
        return 1 - (Math.acos(t) - t * Math.sqrt(1 - t * t)) / Math.PI;
    }
}
