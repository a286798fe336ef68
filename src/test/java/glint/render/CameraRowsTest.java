package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;

import glint.math.Vector3d;
import glint.scene.Camera;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * A row's rays are the camera's rays ({@link PinholeCamera#direction}) bit for bit: through the pixel
 * centres, which a row aims in one loop of its own, and through each pixel's jittered samples.
 */
class CameraRowsTest {

    @Test
    void pixelCentresAreTheCamerasRays() {
        SplittableRandom random = new SplittableRandom(21);
        CameraRows rows = new CameraRows();
        for (int trial = 0; trial < 40; trial++) {
            Vector3d eye = new Vector3d(random.nextDouble(-50, 50), random.nextDouble(-50, 50),
                    random.nextDouble(-50, 50));
            double[] towards = RandomScenes.unitVector(random);
            Vector3d target = eye.add(new Vector3d(towards[0], towards[1], towards[2]));
            int width = 1 + random.nextInt(900), height = 1 + random.nextInt(700);
            int divider = 1 + random.nextInt(Math.min(8, Math.min(width, height)));
            // two fields of view over the same tiles: the second frame must not reuse the first's centres
            for (int frame = 0; frame < 2; frame++) {
                Camera camera = Camera.lookAt(eye, target, new Vector3d(0, 1, 0), random.nextDouble(5, 150));
                assertFrameMatches(rows, new PinholeCamera(camera), width, height, divider, 1, random);
            }
        }
    }

    @Test
    void jitteredSamplesAreTheCamerasRaysThroughThem() {
        SplittableRandom random = new SplittableRandom(22);
        CameraRows rows = new CameraRows();
        for (int trial = 0; trial < 20; trial++) {
            Vector3d eye = new Vector3d(random.nextDouble(-50, 50), random.nextDouble(-50, 50),
                    random.nextDouble(-50, 50));
            double[] towards = RandomScenes.unitVector(random);
            Vector3d target = eye.add(new Vector3d(towards[0], towards[1], towards[2]));
            int width = 1 + random.nextInt(300), height = 1 + random.nextInt(200);
            int divider = 1 + random.nextInt(Math.min(4, Math.min(width, height)));
            Camera camera = Camera.lookAt(eye, target, new Vector3d(0, 1, 0), random.nextDouble(5, 150));
            int side = 2 + random.nextInt(3);
            assertFrameMatches(rows, new PinholeCamera(camera), width, height, divider, side * side, random);
        }
    }

    /**
     * Through a lens, each ray is the camera's ray from its film point (as the pinhole's rows place it)
     * and the lens point of its (pixel, frame, sample), {@link PathSamples#LENS}: origin and direction.
     */
    @Test
    void lensRaysAreTheCamerasRaysThroughTheirFilmAndLensPoints() {
        SplittableRandom random = new SplittableRandom(23);
        CameraRows rows = new CameraRows();
        PathSamples lens = new PathSamples();
        double[] ox = new double[1], oy = new double[1], oz = new double[1];
        double[] dx = new double[1], dy = new double[1], dz = new double[1];
        for (int trial = 0; trial < 20; trial++) {
            Vector3d eye = new Vector3d(random.nextDouble(-50, 50), random.nextDouble(-50, 50),
                    random.nextDouble(-50, 50));
            double[] towards = RandomScenes.unitVector(random);
            Vector3d target = eye.add(new Vector3d(towards[0], towards[1], towards[2]));
            int width = 1 + random.nextInt(200), height = 1 + random.nextInt(150);
            CameraModel camera = CameraModel.of(Camera.lookAt(eye, target, new Vector3d(0, 1, 0),
                    random.nextDouble(5, 150)).withLens(random.nextDouble(0.01, 1), random.nextDouble(0.5, 20)));
            int side = 1 + random.nextInt(4), samples = side * side, frameIndex = random.nextInt(5);
            int x0 = random.nextInt(width), x1 = x0 + 1 + random.nextInt(width - x0);
            rows.prepare(camera, width, height, x0, x1, samples, 0, samples, frameIndex);
            assertEquals(false, rows.oneOrigin());
            int y = random.nextInt(height);
            rows.aim(y);
            for (int x = x0, ray = 0; x < x1; x++) {
                for (int s = 0; s < samples; s++, ray++) {
                    double px = x + 0.5, py = y + 0.5;
                    if (samples > 1) {
                        long h = SamplePattern.hash(y * width + x, frameIndex, s);
                        px = x + (s % side + SamplePattern.jitterU(h)) / side;
                        py = y + (s / side + SamplePattern.jitterV(h)) / side;
                    }
                    lens.begin(y * width + x, frameIndex, s, samples);
                    lens.pair(PathSamples.LENS);
                    camera.ray(px, py, lens.u1, lens.u2, width, height, ox, oy, oz, dx, dy, dz, 0);
                    String where = "sample " + s + " of pixel " + x + ", " + y;
                    assertEquals(ox[0], rows.originX[ray], where);
                    assertEquals(oy[0], rows.originY[ray], where);
                    assertEquals(oz[0], rows.originZ[ray], where);
                    assertEquals(dx[0], rows.dirX[ray], where);
                    assertEquals(dy[0], rows.dirY[ray], where);
                    assertEquals(dz[0], rows.dirZ[ray], where);
                }
            }
        }
    }

    /**
     * Tile by tile, some rows of each, as the tracer goes (the tile's pixel centres are kept between
     * rows): every ray of the row, sample s of pixel x at (x + (s % side + u) / side, y + (s / side + v) / side)
     * with the pattern's jitter (u, v), or the pixel's centre with one sample.
     */
    private static void assertFrameMatches(CameraRows rows, PinholeCamera camera, int width, int height, int divider,
                                           int samples, SplittableRandom random) {
        int side = (int) Math.round(Math.sqrt(samples)), frameIndex = random.nextInt(5);
        for (int column = 0; column < divider; column++) {
            int x0 = column * width / divider, x1 = (column + 1) * width / divider;
            rows.prepare(camera, width, height, x0, x1, samples, 0, samples, frameIndex);
            for (int y = 0; y < height; y += 1 + random.nextInt(height)) {
                rows.aim(y);
                for (int x = x0, ray = 0; x < x1; x++) {
                    for (int s = 0; s < samples; s++, ray++) {
                        double px = x + 0.5, py = y + 0.5;
                        if (samples > 1) {
                            long h = SamplePattern.hash(y * width + x, frameIndex, s);
                            px = x + (s % side + SamplePattern.jitterU(h)) / side;
                            py = y + (s / side + SamplePattern.jitterV(h)) / side;
                        }
                        Vector3d d = camera.direction(px, py, width, height);
                        int i = ray;
                        String where = "sample " + s + " of pixel " + x + ", " + y;
                        assertEquals(d.x(), rows.dirX[i], () -> "x of " + where);
                        assertEquals(d.y(), rows.dirY[i], () -> "y of " + where);
                        assertEquals(d.z(), rows.dirZ[i], () -> "z of " + where);
                    }
                }
            }
        }
    }
}
