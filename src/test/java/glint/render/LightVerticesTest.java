package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The light points camera vertices merge with, against brute force on seeded random paths: the grid
 * finds every point within the radius exactly once, and only points a camera vertex can merge with (past
 * the light, on a diffuse surface); a point reads back as it was written, with its path.
 */
class LightVerticesTest {

    @Test
    void theGridFindsEveryMergeablePointWithinTheRadiusOnce() {
        SplittableRandom random = new SplittableRandom(5);
        LightVertices vertices = new LightVertices();
        for (int round = 0; round < 3; round++) { // the arrays reused, as pass after pass
            int paths = 300 + round * 400;
            double radius = 0.15 + 0.1 * round;
            List<double[]> mergeable = fill(vertices, paths, radius, random);
            vertices.finish();
            int[] near = new int[8];
            int found = 0;
            for (int query = 0; query < 500; query++) {
                double x = random.nextDouble(-1, 1), y = random.nextDouble(-1, 1), z = random.nextDouble(-1, 1);
                int expected = 0;
                for (double[] p : mergeable) {
                    double dx = p[0] - x, dy = p[1] - y, dz = p[2] - z;
                    expected += dx * dx + dy * dy + dz * dz < radius * radius ? 1 : 0;
                }
                int seen = 0;
                for (int b = 0, n = vertices.bucketsNear(x, y, z, near); b < n; b++) {
                    for (int i = vertices.bucketFrom(near[b]); i < vertices.bucketTo(near[b]); i++) {
                        int v = vertices.vertexAt(i);
                        assertTrue(vertices.indexOnPath(v) > 0, "never the light's own point");
                        seen += vertices.distance2At(i, x, y, z) < radius * radius ? 1 : 0;
                    }
                }
                assertEquals(expected, seen, "query " + query + " of round " + round);
                found += seen;
            }
            assertTrue(found > 200, "points found: " + found);
        }
    }

    @Test
    void aPointReadsBackWithItsPath() {
        LightVertices vertices = new LightVertices();
        vertices.begin(1, 1);
        BdptVertex[] path = {vertex(0, 0, 5, BdptVertex.LIGHT, false), vertex(1, 2, 3, BdptVertex.SURFACE, true),
                vertex(4, 5, 6, BdptVertex.SURFACE, true)};
        path[1].delta = true;
        path[2].pdfFwd = 0.25;
        path[2].pdfRev = 0.5;
        path[2].setBeta(1, 2, 3);
        path[2].surface.offset = 1e-3;
        path[2].surface.skipNear = 7;
        path[2].surface.insideFar = 9;
        vertices.chunk(0).clear();
        vertices.chunk(0).add(path, 3);
        vertices.finish();
        int v = 2; // the third point of the only path
        assertEquals(2, vertices.indexOnPath(v));
        BdptVertex[] read = {new BdptVertex(), new BdptVertex(), new BdptVertex()};
        vertices.loadPath(v, read);
        assertEquals(BdptVertex.LIGHT, read[0].kind);
        assertEquals(5, read[0].surface.pz);
        assertTrue(read[1].delta);
        assertEquals(6, read[2].surface.pz);
        assertEquals(0.25, read[2].pdfFwd);
        assertEquals(0.5, read[2].pdfRev);
        assertEquals(3, read[2].betaB);
        assertEquals(path[2].surface.material, read[2].surface.material);
        BdptVertex[] whole = {new BdptVertex(), new BdptVertex(), new BdptVertex(), new BdptVertex()};
        assertEquals(3, vertices.loadPathNumber(0, whole));
        assertEquals(6, whole[2].surface.pz);
        assertEquals(1e-3, whole[2].surface.offset);
        assertEquals(7, whole[2].surface.skipNear);
        assertEquals(9, whole[2].surface.insideFar);
    }

    /** Each path reads back whole by its number, in the order the chunks traced them. */
    @Test
    void aPathReadsBackByItsNumber() {
        SplittableRandom random = new SplittableRandom(8);
        LightVertices vertices = new LightVertices();
        int paths = 3 * LightVertices.CHUNK_PATHS + 5;
        int chunks = vertices.begin(paths, 0);
        int[] length = new int[paths];
        BdptVertex[] path = new BdptVertex[5];
        for (int c = 0; c < chunks; c++) {
            LightVertices.Chunk chunk = vertices.chunk(c);
            chunk.clear();
            for (int p = vertices.firstPath(c); p < vertices.firstPath(c) + vertices.pathsIn(c); p++) {
                length[p] = random.nextInt(1, path.length + 1);
                for (int k = 0; k < length[p]; k++) {
                    path[k] = vertex(p, k, 0, k == 0 ? BdptVertex.LIGHT : BdptVertex.SURFACE, true);
                }
                chunk.add(path, length[p]);
            }
        }
        vertices.finish();
        BdptVertex[] read = new BdptVertex[5];
        for (int k = 0; k < read.length; k++) {
            read[k] = new BdptVertex();
        }
        for (int p = 0; p < paths; p++) {
            assertEquals(length[p], vertices.loadPathNumber(p, read));
            for (int k = 0; k < length[p]; k++) {
                assertEquals(p, read[k].surface.px, "path " + p);
                assertEquals(k, read[k].surface.py, "vertex " + k + " of path " + p);
            }
        }
    }

    /** Random paths into the chunks; returns the points that can be merged with. */
    private static List<double[]> fill(LightVertices vertices, int paths, double radius, SplittableRandom random) {
        int chunks = vertices.begin(paths, radius);
        List<double[]> mergeable = new ArrayList<>();
        BdptVertex[] path = new BdptVertex[6];
        for (int c = 0; c < chunks; c++) {
            LightVertices.Chunk chunk = vertices.chunk(c);
            chunk.clear();
            for (int p = 0; p < vertices.pathsIn(c); p++) {
                int n = random.nextInt(1, path.length + 1);
                for (int k = 0; k < n; k++) {
                    boolean diffuse = random.nextInt(4) > 0;
                    path[k] = vertex(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1),
                            k == 0 ? BdptVertex.LIGHT : BdptVertex.SURFACE, diffuse);
                    if (k > 0 && diffuse) {
                        mergeable.add(new double[] {path[k].surface.px, path[k].surface.py, path[k].surface.pz});
                    }
                }
                chunk.add(path, n);
            }
        }
        return mergeable;
    }

    private static BdptVertex vertex(double x, double y, double z, int kind, boolean diffuse) {
        BdptVertex v = new BdptVertex();
        v.setPoint(x, y, z);
        v.kind = kind;
        v.connectible = diffuse;
        v.diffuse = diffuse;
        return v;
    }
}
