package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * A sphere's cone seen from the light holds every direction within its half-angle widened by the
 * margin, and none much beyond it; a light inside a sphere finds that sphere in every direction.
 * Shadow rays through the cones are compared with full tests in {@link LightBufferTest}.
 */
class LightConesTest {

    @Test
    void aConeHoldsTheWidenedHalfAngleAndLittleMore() {
        SplittableRandom random = new SplittableRandom(21);
        for (int trial = 0; trial < 3000; trial++) {
            RandomScenes.SeenSphere seen = RandomScenes.SeenSphere.random(random);
            double[] light = {random.nextDouble(-5, 5), random.nextDouble(-5, 5), random.nextDouble(-5, 5)};
            LightCones cones = LightCones.build(seen.from(light[0], light[1], light[2]), 1, light[0], light[1],
                    light[2]);
            double[] towards = seen.towards();
            for (int i = 0; i < 100; i++) {
                double[] d = RandomScenes.atAngle(towards, seen.angleWithinMargin(i, random), random);
                // holds() takes the shadow ray's direction, towards the light
                assertTrue(cones.holds(0, -d[0], -d[1], -d[2]), "trial " + trial + ", direction " + i);
                double outside = Math.min(Math.PI,
                        seen.halfAngle() + 3 * ConeCells.ANGLE_MARGIN + random.nextDouble(0, 1));
                double[] e = RandomScenes.atAngle(towards, outside, random);
                assertFalse(cones.holds(0, -e[0], -e[1], -e[2]), "trial " + trial + ", outside " + i);
            }
        }
    }

    @Test
    void aLightInsideASphereFindsItInEveryDirection() {
        double[] spheres = {0, 0, 0, 2, 5, 0, 0, 1};
        LightCones cones = LightCones.build(spheres, 2, 1.8, 0.2, 0);
        SplittableRandom random = new SplittableRandom(3);
        int second = 0;
        for (int i = 0; i < 1000; i++) {
            double[] d = RandomScenes.unitVector(random);
            assertTrue(cones.holds(0, d[0], d[1], d[2]), "direction " + i);
            second += cones.holds(1, d[0], d[1], d[2]) ? 1 : 0;
        }
        // the sphere outside fills a cone of half-angle asin(1 / 3.21): about 2.6 % of directions
        assertTrue(second > 5 && second < 60, second + " of 1000");
        // only the sphere outside limits the offsets
        assertEquals(Math.sin(ConeCells.ANGLE_MARGIN) * (Math.sqrt(3.2 * 3.2 + 0.2 * 0.2) - 1), cones.maxOffset, 1e-15);
    }
}
