package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;

import glint.math.Vector3d;
import glint.scene.Camera;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The rays through pixel centres, which a row aims in one loop of its own, are the rays
 * aimed one point at a time, bit for bit.
 */
class CameraRowsTest {

    @Test
    void pixelCentresAreAimedAsSinglePointsAre() {
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
                assertFrameMatches(rows, new CameraBasis(camera), width, height, divider, random);
            }
        }
    }

    /** Tile by tile, some rows of each, as the tracer goes: the tile's pixel centres are kept between rows. */
    private static void assertFrameMatches(CameraRows rows, CameraBasis camera, int width, int height, int divider,
                                           SplittableRandom random) {
        CameraRows single = new CameraRows();
        for (int column = 0; column < divider; column++) {
            int x0 = column * width / divider, x1 = (column + 1) * width / divider;
            rows.prepare(camera, width, height, x0, x1, 1, 0, 1, 0);
            single.prepare(camera, width, height, x0, x1, 1, 0, 1, 0);
            for (int y = 0; y < height; y += 1 + random.nextInt(height)) {
                rows.aim(y);
                for (int x = x0; x < x1; x++) {
                    single.aimThrough(x - x0, x + 0.5, y + 0.5);
                    int ray = x - x0, pixel = x, row = y;
                    assertEquals(single.dirX[ray], rows.dirX[ray], () -> "x of pixel " + pixel + ", " + row);
                    assertEquals(single.dirY[ray], rows.dirY[ray], () -> "y of pixel " + pixel + ", " + row);
                    assertEquals(single.dirZ[ray], rows.dirZ[ray], () -> "z of pixel " + pixel + ", " + row);
                }
            }
        }
    }
}
