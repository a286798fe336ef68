package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * A row's point-light samples ({@link RowHits#samplePointLight}) against values worked out by hand,
 * and its cone margins ({@link RowHits#coneMargins}) against {@link LightCones#holds}.
 */
class RowHitsTest {

    private static final double LIGHT_X = 1, LIGHT_Y = 3, LIGHT_Z = -2;

    @Test
    void aHitBelowTheLightFacingItGetsTheInverseSquareFalloff() {
        RowHits hits = hitsAt(new double[][] {{1, 1, -2, 0, 1, 0}});
        hits.samplePointLight(1, LIGHT_X, LIGHT_Y, LIGHT_Z, 8, 4, 2);
        assertEquals(1, hits.cosLight[0]);
        assertEquals(2, hits.lightDistance[0]);
        assertEquals(0, hits.toLightX[0]);
        assertEquals(1, hits.toLightY[0]);
        assertEquals(0, hits.toLightZ[0]);
        assertEquals(2, hits.lightR[0]); // 8 / 2^2
        assertEquals(1, hits.lightG[0]);
        assertEquals(0.5, hits.lightB[0]);
    }

    @Test
    void aHitSeeingTheLightAtAnAngleGetsItsCosine() {
        // the light 3 up and 4 across: distance 5, n.l = 3/5 for a normal straight up
        RowHits hits = hitsAt(new double[][] {{-3, 0, -2, 0, 1, 0}, {1, 0, 2, 0, 1, 0}});
        hits.samplePointLight(2, LIGHT_X, LIGHT_Y, LIGHT_Z, 25, 25, 25);
        for (int j = 0; j < 2; j++) {
            assertEquals(5, hits.lightDistance[j], 1e-15);
            assertEquals(0.6, hits.cosLight[j], 1e-15);
            assertEquals(0.6, hits.lightR[j], 1e-15); // 25 / 25 x 0.6
        }
        assertEquals(0.8, hits.toLightX[0], 1e-15);
        assertEquals(-0.8, hits.toLightZ[1], 1e-15);
    }

    @Test
    void aHitAtTheLightItselfIsNotLit() {
        RowHits hits = hitsAt(new double[][] {{LIGHT_X, LIGHT_Y, LIGHT_Z, 0, 1, 0}, {1, 1, -2, 0, 1, 0}});
        hits.samplePointLight(2, LIGHT_X, LIGHT_Y, LIGHT_Z, 8, 8, 8);
        assertFalse(hits.cosLight[0] > 0, "n.l at the light: " + hits.cosLight[0]);
        assertEquals(1, hits.cosLight[1]); // its neighbour keeps its own sample
    }

    @Test
    void theMarginOfASphereStraightBelowTheLightIsItsConesWidthAlongTheAxis() {
        // a sphere of radius 1, 2 below the light: half-angle 30 degrees (plus the cones' widening)
        LightCones cones = LightCones.build(new double[] {0, -2, 0, 1}, 1, 0, 0, 0);
        RowHits hits = directionsToLight(new double[][] {{0, 1, 0}, {1, 0, 0}, {0, -1, 0}});
        hits.coneMargins(3, cones);
        assertEquals(1 - Math.cos(Math.toRadians(30)), hits.coneMargin[0], 1e-3); // from straight below: inside
        assertEquals(-Math.cos(Math.toRadians(30)), hits.coneMargin[1], 1e-3); // from the side: outside
        assertEquals(-1 - Math.cos(Math.toRadians(30)), hits.coneMargin[2], 1e-3); // from above: far outside
    }

    @Test
    void aMarginIsBelowZeroExactlyWhereNoConeHoldsTheDirection() {
        SplittableRandom random = new SplittableRandom(20261122);
        for (int scene = 0; scene < 200; scene++) {
            int count = 1 + random.nextInt(4);
            double[] spheres = new double[4 * count];
            for (int i = 0; i < count; i++) {
                for (int c = 0; c < 3; c++) {
                    spheres[4 * i + c] = random.nextDouble() * 8 - 4;
                }
                spheres[4 * i + 3] = 0.1 + random.nextDouble() * 2; // some hold the light: every direction
            }
            LightCones cones = LightCones.build(spheres, count, 0, 0, 0);
            double[][] directions = new double[64][];
            for (int j = 0; j < directions.length; j++) {
                // towards the light: many at a cone's edge, as a shadow ray near a silhouette is
                int near = random.nextInt(count);
                directions[j] = j % 2 == 0 ? RandomScenes.unitVector(random) : nearEdge(cones, near, random);
            }
            RowHits hits = directionsToLight(directions);
            hits.coneMargins(directions.length, cones);
            for (int j = 0; j < directions.length; j++) {
                double[] d = directions[j];
                boolean held = false;
                for (int i = 0; i < count; i++) {
                    held |= cones.holds(i, d[0], d[1], d[2]);
                }
                assertEquals(held, hits.coneMargin[j] >= 0, "scene " + scene + ", direction " + j);
            }
        }
    }

    @Test
    void aConeHoldingEveryDirectionGivesEveryHitAMargin() {
        LightCones cones = LightCones.build(new double[] {0, 0.5, 0, 1}, 1, 0, 0, 0); // the light inside it
        RowHits hits = directionsToLight(new double[][] {{0, 1, 0}, {0, -1, 0}, {0.6, 0, 0.8}});
        hits.coneMargins(3, cones);
        for (int j = 0; j < 3; j++) {
            assertTrue(hits.coneMargin[j] >= 1, "margin " + hits.coneMargin[j]);
        }
    }

    /**
     * A unit direction to the light whose direction from it lies within a millionth of cone i's
     * half-angle of its edge; any direction where the cone holds every one.
     */
    private static double[] nearEdge(LightCones cones, int i, SplittableRandom random) {
        double cos = cones.cones[4 * i + 3];
        if (cos < -1) {
            return RandomScenes.unitVector(random);
        }
        double[] axis = {cones.cones[4 * i], cones.cones[4 * i + 1], cones.cones[4 * i + 2]};
        double angle = Math.acos(cos) * (1 + (random.nextDouble() - 0.5) * 1e-6);
        double[] fromLight = RandomScenes.atAngle(axis, angle, random);
        return new double[] {-fromLight[0], -fromLight[1], -fromLight[2]};
    }

    /** Matte slots whose unit directions to the light are the given ones. */
    private static RowHits directionsToLight(double[][] directions) {
        RowHits hits = new RowHits();
        hits.fit(directions.length);
        for (int j = 0; j < directions.length; j++) {
            hits.toLightX[j] = directions[j][0];
            hits.toLightY[j] = directions[j][1];
            hits.toLightZ[j] = directions[j][2];
        }
        return hits;
    }

    /** Matte slots holding the given points and normals, {x, y, z, nx, ny, nz} each. */
    private static RowHits hitsAt(double[][] points) {
        RowHits hits = new RowHits();
        hits.fit(points.length);
        for (int j = 0; j < points.length; j++) {
            double[] p = points[j];
            hits.px[j] = p[0];
            hits.py[j] = p[1];
            hits.pz[j] = p[2];
            hits.nx[j] = p[3];
            hits.ny[j] = p[4];
            hits.nz[j] = p[5];
        }
        return hits;
    }
}
