package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import org.junit.jupiter.api.Test;

/** A row's point-light samples ({@link RowHits#samplePointLight}) against values worked out by hand. */
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
