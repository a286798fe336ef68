package glint.render;

import glint.shading.Surface;
import java.util.Arrays;

/**
 * The light subpaths of one pass that camera paths merge with (vertex merging, {@link BdptIntegrator}):
 * every vertex of every path, as flat arrays, and a hash grid over those a camera vertex can merge with
 * (a surface point that is not delta, past the light itself). The paths are traced in chunks of
 * {@link #CHUNK_PATHS}, each by whichever render thread takes it, into the chunk's own arrays; joined in
 * chunk order, they and the grid are the same whatever the threads, so that the image is too. The arrays
 * grow to the largest pass and are kept: a pass allocates nothing once they have.
 */
final class LightVertices {

    /** Light subpaths a render thread traces at a time. */
    static final int CHUNK_PATHS = 256;

    // a vertex's numbers, in order: its point, normal, the direction back along its path, its far
    // light's direction, the path's throughput, its densities, its surface's cosine and the offset of
    // rays leaving it
    private static final int PX = 0, NX = 3, WO = 6, FAR = 9, BETA = 12, PDF_FWD = 15, PDF_REV = 16, COS = 17;
    private static final int OFFSET = 18, DOUBLES = 19;
    // and its kind, light, material, flags, and the primitives rays leaving it skip and travel inside
    private static final int KIND = 0, LIGHT = 1, MATERIAL = 2, FLAGS = 3, SKIP_NEAR = 4, SKIP_FAR = 5;
    private static final int INSIDE_NEAR = 6, INSIDE_FAR = 7, INTS = 8;
    private static final int DELTA = 1, DELTA_LIGHT = 2, CONNECTIBLE = 4, FRONT = 8, DIFFUSE = 16;

    /** One chunk's paths: their vertices one after the other, and each path's vertex count. */
    static final class Chunk {
        double[] d = new double[0];
        int[] i = new int[0];
        int vertices;
        final int[] pathLength = new int[CHUNK_PATHS];
        int paths;

        void clear() {
            vertices = 0;
            paths = 0;
        }

        /** Adds a path of the first n vertices of {@code path}. */
        void add(BdptVertex[] path, int n) {
            if ((vertices + n) * DOUBLES > d.length) {
                int size = Math.max(2 * d.length / DOUBLES, vertices + n + 64);
                d = Arrays.copyOf(d, size * DOUBLES);
                i = Arrays.copyOf(i, size * INTS);
            }
            for (int k = 0; k < n; k++) {
                write(path[k], vertices + k);
            }
            vertices += n;
            pathLength[paths++] = n;
        }

        private void write(BdptVertex v, int at) {
            int o = at * DOUBLES, q = at * INTS;
            Surface s = v.surface;
            d[o + PX] = s.px;
            d[o + PX + 1] = s.py;
            d[o + PX + 2] = s.pz;
            d[o + NX] = s.nx;
            d[o + NX + 1] = s.ny;
            d[o + NX + 2] = s.nz;
            d[o + WO] = v.woX;
            d[o + WO + 1] = v.woY;
            d[o + WO + 2] = v.woZ;
            d[o + FAR] = v.farX;
            d[o + FAR + 1] = v.farY;
            d[o + FAR + 2] = v.farZ;
            d[o + BETA] = v.betaR;
            d[o + BETA + 1] = v.betaG;
            d[o + BETA + 2] = v.betaB;
            d[o + PDF_FWD] = v.pdfFwd;
            d[o + PDF_REV] = v.pdfRev;
            d[o + COS] = s.cosIncident;
            d[o + OFFSET] = s.offset;
            i[q + KIND] = v.kind;
            i[q + LIGHT] = v.light;
            i[q + MATERIAL] = s.material;
            i[q + FLAGS] = (v.delta ? DELTA : 0) | (v.deltaLight ? DELTA_LIGHT : 0) | (v.connectible ? CONNECTIBLE : 0)
                    | (s.front ? FRONT : 0) | (v.diffuse ? DIFFUSE : 0);
            i[q + SKIP_NEAR] = s.skipNear;
            i[q + SKIP_FAR] = s.skipFar;
            i[q + INSIDE_NEAR] = s.insideNear;
            i[q + INSIDE_FAR] = s.insideFar;
        }
    }

    private Chunk[] chunks = new Chunk[0];
    private int chunkCount;
    /** Every path's vertices, in path order. */
    private double[] d = new double[0];
    private int[] ints = new int[0];
    /** Per vertex: the index of its path's first vertex. */
    private int[] pathStart = new int[0];
    /** Per path: the index of its first vertex, and (one past the last path) the vertex count. */
    private int[] firstVertex = new int[1];
    private int vertices, paths;
    /** The vertices a camera vertex can merge with, in order, and the grid's buckets of them. */
    private int[] mergeable = new int[0];
    private int[] bucketStart = new int[1], bucketed = new int[0];
    /**
     * The gridded vertices' positions, x y z, in the grid's order: a lookup reads the candidates of a bucket
     * from one run of memory rather than from their paths all over {@link #d}.
     */
    private double[] bucketedPoint = new double[0];
    /** Scratch: where the next vertex of each bucket goes while the grid is filled. */
    private int[] fill = new int[0];
    private int buckets = 1;
    private double radius, cellSize;

    /**
     * Makes ready for {@code paths} light subpaths in chunks, merged with within {@code mergeRadius} (0: not
     * merged with); returns the chunk count.
     */
    int begin(int pathCount, double mergeRadius) {
        paths = pathCount;
        radius = mergeRadius;
        cellSize = 2 * mergeRadius;
        chunkCount = (pathCount + CHUNK_PATHS - 1) / CHUNK_PATHS;
        if (chunks.length < chunkCount) {
            Chunk[] more = Arrays.copyOf(chunks, chunkCount);
            for (int c = chunks.length; c < chunkCount; c++) {
                more[c] = new Chunk();
            }
            chunks = more;
        }
        return chunkCount;
    }

    Chunk chunk(int c) {
        return chunks[c];
    }

    /** The light subpaths traced this pass. */
    int paths() {
        return paths;
    }

    /** The paths of chunk c: [c * CHUNK_PATHS, that plus its size). */
    int firstPath(int c) {
        return c * CHUNK_PATHS;
    }

    int pathsIn(int c) {
        return Math.min(CHUNK_PATHS, paths - c * CHUNK_PATHS);
    }

    /**
     * Joins the chunks, traced, in order and, where they are merged with, grids the vertices that can merge
     * with cells of twice the merge radius.
     */
    void finish() {
        vertices = 0;
        for (int c = 0; c < chunkCount; c++) {
            vertices += chunks[c].vertices;
        }
        if (d.length < vertices * DOUBLES) {
            d = new double[vertices * DOUBLES];
            ints = new int[vertices * INTS];
            pathStart = new int[vertices];
            mergeable = new int[vertices];
            bucketed = new int[vertices];
            bucketedPoint = new double[3 * vertices];
        }
        if (firstVertex.length < paths + 1) {
            firstVertex = new int[paths + 1];
        }
        int at = 0, count = 0, path = 0;
        for (int c = 0; c < chunkCount; c++) {
            Chunk chunk = chunks[c];
            System.arraycopy(chunk.d, 0, d, at * DOUBLES, chunk.vertices * DOUBLES);
            System.arraycopy(chunk.i, 0, ints, at * INTS, chunk.vertices * INTS);
            for (int p = 0, v = at; p < chunk.paths; p++) {
                int n = chunk.pathLength[p];
                firstVertex[path++] = v;
                for (int k = 0; k < n; k++) {
                    pathStart[v + k] = v;
                    int flags = ints[(v + k) * INTS + FLAGS];
                    if (k > 0 && ints[(v + k) * INTS + KIND] == BdptVertex.SURFACE && (flags & DIFFUSE) != 0) {
                        mergeable[count++] = v + k;
                    }
                }
                v += n;
            }
            at += chunk.vertices;
        }
        firstVertex[path] = vertices;
        grid(radius > 0 ? count : 0);
    }

    /** Counts the mergeable vertices into buckets by their cell, in their order. */
    private void grid(int count) {
        int size = Integer.highestOneBit(Math.max(1, count)) << 1;
        if (bucketStart.length < size + 1) {
            bucketStart = new int[size + 1];
        }
        buckets = size;
        Arrays.fill(bucketStart, 0, size + 1, 0);
        for (int k = 0; k < count; k++) {
            bucketStart[bucketOf(mergeable[k]) + 1]++;
        }
        for (int b = 0; b < size; b++) {
            bucketStart[b + 1] += bucketStart[b];
        }
        int[] next = bucketFill(size);
        for (int k = 0; k < count; k++) {
            int v = mergeable[k];
            int at = next[bucketOf(v)]++;
            bucketed[at] = v;
            System.arraycopy(d, v * DOUBLES + PX, bucketedPoint, 3 * at, 3);
        }
    }

    private int[] bucketFill(int size) {
        if (fill.length < size) {
            fill = new int[size];
        }
        System.arraycopy(bucketStart, 0, fill, 0, size);
        return fill;
    }

    private int bucketOf(int v) {
        int o = v * DOUBLES;
        return bucket(cell(d[o + PX]), cell(d[o + PX + 1]), cell(d[o + PX + 2]));
    }

    private int cell(double x) {
        return (int) Math.floor(x / cellSize);
    }

    private int bucket(int x, int y, int z) {
        return ((x * 73856093) ^ (y * 19349663) ^ (z * 83492791)) & (buckets - 1);
    }

    double radius() {
        return radius;
    }

    /**
     * The buckets a sphere of the merge radius around (x, y, z) may reach, each once, into
     * {@code out} (8 at most); returns their count. Their vertices lie in [{@link #bucketFrom},
     * {@link #bucketTo}) of {@link #vertexAt}.
     */
    int bucketsNear(double x, double y, double z, int[] out) {
        int x0 = cell(x - radius), y0 = cell(y - radius), z0 = cell(z - radius);
        int n = 0;
        for (int k = 0; k < 8; k++) {
            int b = bucket(x0 + (k & 1), y0 + (k >> 1 & 1), z0 + (k >> 2));
            boolean seen = false;
            for (int j = 0; j < n; j++) {
                seen |= out[j] == b;
            }
            if (!seen) {
                out[n++] = b;
            }
        }
        return n;
    }

    int bucketFrom(int b) {
        return bucketStart[b];
    }

    int bucketTo(int b) {
        return bucketStart[b + 1];
    }

    /** The k-th vertex of the grid's order. */
    int vertexAt(int k) {
        return bucketed[k];
    }

    /** The squared distance from the k-th vertex of the grid's order to (x, y, z). */
    double distance2At(int k, double x, double y, double z) {
        int o = 3 * k;
        double dx = bucketedPoint[o] - x, dy = bucketedPoint[o + 1] - y, dz = bucketedPoint[o + 2] - z;
        return dx * dx + dy * dy + dz * dz;
    }

    /** Vertex v's place on its path: 0 for the light's own. */
    int indexOnPath(int v) {
        return v - pathStart[v];
    }

    /** Loads light subpath p's vertices into path[0 ..]; returns their count. */
    int loadPathNumber(int p, BdptVertex[] path) {
        return loadVertices(firstVertex[p], firstVertex[p + 1], path);
    }

    /** Loads vertex v and the ones before it on its path into path[0 .. its index]. */
    void loadPath(int v, BdptVertex[] path) {
        loadVertices(pathStart[v], v + 1, path);
    }

    /** Loads vertices [from, to) into path[0 ..]; returns their count. */
    private int loadVertices(int from, int to, BdptVertex[] path) {
        for (int v = from; v < to; v++) {
            load(v, path[v - from]);
        }
        return to - from;
    }

    private void load(int v, BdptVertex out) {
        int o = v * DOUBLES, q = v * INTS;
        Surface s = out.surface;
        s.px = d[o + PX];
        s.py = d[o + PX + 1];
        s.pz = d[o + PX + 2];
        s.nx = d[o + NX];
        s.ny = d[o + NX + 1];
        s.nz = d[o + NX + 2];
        s.cosIncident = d[o + COS];
        out.woX = d[o + WO];
        out.woY = d[o + WO + 1];
        out.woZ = d[o + WO + 2];
        out.farX = d[o + FAR];
        out.farY = d[o + FAR + 1];
        out.farZ = d[o + FAR + 2];
        out.betaR = d[o + BETA];
        out.betaG = d[o + BETA + 1];
        out.betaB = d[o + BETA + 2];
        out.pdfFwd = d[o + PDF_FWD];
        out.pdfRev = d[o + PDF_REV];
        out.kind = ints[q + KIND];
        out.light = ints[q + LIGHT];
        s.material = ints[q + MATERIAL];
        int flags = ints[q + FLAGS];
        out.delta = (flags & DELTA) != 0;
        out.deltaLight = (flags & DELTA_LIGHT) != 0;
        out.connectible = (flags & CONNECTIBLE) != 0;
        out.diffuse = (flags & DIFFUSE) != 0;
        s.front = (flags & FRONT) != 0;
        s.offset = d[o + OFFSET];
        s.skipNear = ints[q + SKIP_NEAR];
        s.skipFar = ints[q + SKIP_FAR];
        s.insideNear = ints[q + INSIDE_NEAR];
        s.insideFar = ints[q + INSIDE_FAR];
    }
}
