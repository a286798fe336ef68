package glint.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.accel.Candidates;
import glint.accel.FlatList;
import glint.accel.Frustum;
import glint.accel.TraversalStack;
import glint.geometry.Intersect;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * A row's gathered primitives, each narrowed to the rays whose screen x its box spans
 * ({@link CameraRows#narrow}), give every ray of the row the hit the whole search gives, and every
 * ray left out of a primitive's range misses it: on seeded random scenes and cameras, with one
 * sample a pixel and with jittered samples.
 */
class NarrowedRowsTest {

    @Test
    void aNarrowedRowFindsTheHitsOfTheWholeSearch() {
        Random random = new Random(20_261_203L);
        long searched = 0, all = 0;
        for (int trial = 0; trial < 24; trial++) {
            RenderScene scene = RenderScene.compile(Renders.scene(RandomScenes.withSpheres(random, 30)),
                    new RenderSettings(Shading.COOK_TORRANCE, 5, 0, Renders.EPSILON), FlatList::new);
            int width = 40 + random.nextInt(200), height = 30 + random.nextInt(150);
            int samples = trial % 3 == 0 ? 4 : 1, divider = 1 + random.nextInt(4);
            int x0 = random.nextInt(width / divider), x1 = width - random.nextInt(width / divider);
            CameraRows rows = new CameraRows();
            rows.prepare(scene.camera, width, height, x0, x1, samples, 0, samples, trial);
            int rays = (x1 - x0) * samples;
            Frustum frustum = new Frustum();
            Candidates candidates = new Candidates();
            TraversalStack stack = scene.aggregate.newStack();
            for (int y = 0; y < height; y += 1 + random.nextInt(8)) {
                rows.aim(y);
                rows.frustum(y, frustum);
                scene.aggregate.gather(frustum, candidates, stack);
                double[] wholeT = new double[rays], narrowT = new double[rays];
                int[] whole = new int[rays], narrow = new int[rays];
                candidates.nearestFromOrigin(scene.primitives, eyeX(scene), eyeY(scene), eyeZ(scene), rows.dirX,
                        rows.dirY, rows.dirZ, rays, wholeT, whole);
                rows.narrow(candidates, scene.primitives);
                candidates.nearestFromOrigin(scene.primitives, eyeX(scene), eyeY(scene), eyeZ(scene), rows.dirX,
                        rows.dirY, rows.dirZ, rays, narrowT, narrow);
                String where = "trial " + trial + ", row " + y;
                assertArrayEquals(whole, narrow, where);
                assertArrayEquals(wholeT, narrowT, where);
                for (int i = 0; i < candidates.count(); i++) {
                    int p = candidates.primitive(i);
                    for (int r = 0; r < rays; r++) {
                        all++;
                        if (candidates.searches(i, r)) {
                            searched++;
                        } else {
                            double t = scene.primitives.intersect(p, eyeX(scene), eyeY(scene), eyeZ(scene),
                                    rows.dirX[r], rows.dirY[r], rows.dirZ[r], Intersect.MISS);
                            assertEquals(Intersect.MISS, t, where + ": ray " + r + " left out of primitive " + p);
                        }
                    }
                }
            }
        }
        assertTrue(searched < all / 2, "the ranges leave out most tests: " + searched + " of " + all);
    }

    private static double eyeX(RenderScene scene) {
        return ((PinholeCamera) scene.camera).eyeX();
    }

    private static double eyeY(RenderScene scene) {
        return ((PinholeCamera) scene.camera).eyeY();
    }

    private static double eyeZ(RenderScene scene) {
        return ((PinholeCamera) scene.camera).eyeZ();
    }
}
