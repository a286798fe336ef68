package glint.study;

import glint.geometry.Intersect;

/**
 * What each pixel of a {@link ShadowScene} (at the origin, in double precision, where rounding is
 * ~1e-16) truly shows: lit, in a cast shadow, or excluded because a rounding-sized change could flip
 * it. A pixel is excluded when its camera ray passes within {@link #MARGIN} of a sphere's silhouette,
 * meets nothing or the floor beyond 100 units, its surface faces the light at a cosine below MARGIN,
 * or its shadow ray passes within MARGIN of a sphere's surface. For a shadow pixel, the depth is how
 * deep the shadow ray passes inside the occluder (radius minus the centre's distance from the
 * segment); for a lit pixel, how far it clears every other sphere and how high the light stands
 * over the tangent plane (an origin moved along n by h sees the light h lower). Moving the ray's origin by less
 * than that cannot change the answer: every point of the moved segment lies within the move of the
 * old one. So a lit pixel shown dark although its clearance exceeds the offset is acne (the ray met
 * the surface it left, or rounding moved the geometry); one whose clearance is below the offset may
 * be the offset itself pushing the origin into a neighbour (overshoot).
 */
public final class ShadowTruth {

    public static final double MARGIN = 1e-3;

    public static final byte EXCLUDED = 0;
    public static final byte LIT = 1;
    public static final byte SHADOW = 2;

    private final byte[] kind;
    private final double[] depth;
    private final double[] hitPoint;

    private ShadowTruth(byte[] kind, double[] depth, double[] hitPoint) {
        this.kind = kind;
        this.depth = depth;
        this.hitPoint = hitPoint;
    }

    public byte kind(int pixel) {
        return kind[pixel];
    }

    /** For a shadow pixel how deep its shadow ray passes inside an occluder, for a lit one its clearance. */
    public double depth(int pixel) {
        return depth[pixel];
    }

    /** |p + (s, s, s)|: the magnitude of the pixel's hit point once the scene is moved by s. */
    public double hitPointNorm(int pixel, double s) {
        double x = hitPoint[3 * pixel] + s, y = hitPoint[3 * pixel + 1] + s, z = hitPoint[3 * pixel + 2] + s;
        return Math.sqrt(x * x + y * y + z * z);
    }

    public int pixels() {
        return kind.length;
    }

    public int count(byte k) {
        int n = 0;
        for (byte b : kind) {
            n += b == k ? 1 : 0;
        }
        return n;
    }

    public static ShadowTruth of(ShadowScene scene) {
        int w = scene.width(), h = scene.height();
        byte[] kind = new byte[w * h];
        double[] depth = new double[w * h];
        double[] hitPoint = new double[3 * w * h];
        double ex = scene.eye().x(), ey = scene.eye().y(), ez = scene.eye().z();
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double[] d = scene.direction(x, y);
                int pixel = y * w + x;
                double best = Intersect.MISS;
                double[] hitSphere = null;
                boolean nearSilhouette = false;
                for (double[] s : scene.spheres()) {
                    if (Math.abs(lineDistance(s, ex, ey, ez, d) - s[3]) < MARGIN) {
                        nearSilhouette = true;
                    }
                    double t = Intersect.sphereBefore(s[0], s[1], s[2], s[3], ex, ey, ez, d[0], d[1], d[2],
                            Intersect.MISS);
                    if (t < best) {
                        best = t;
                        hitSphere = s;
                    }
                }
                if (scene.hasFloor()) {
                    double t = Intersect.planeBefore(0, 1, 0, scene.floorY(), ex, ey, ez, d[0], d[1], d[2],
                            Intersect.MISS);
                    if (t < best) {
                        best = t;
                        hitSphere = null;
                    }
                }
                if (nearSilhouette || best > 100) {
                    continue;
                }
                double px = ex + best * d[0], py = ey + best * d[1], pz = ez + best * d[2];
                hitPoint[3 * pixel] = px;
                hitPoint[3 * pixel + 1] = py;
                hitPoint[3 * pixel + 2] = pz;
                double nx = 0, ny = 1, nz = 0;
                if (hitSphere != null) {
                    nx = (px - hitSphere[0]) / hitSphere[3];
                    ny = (py - hitSphere[1]) / hitSphere[3];
                    nz = (pz - hitSphere[2]) / hitSphere[3];
                }
                double lx = scene.light().x() - px, ly = scene.light().y() - py, lz = scene.light().z() - pz;
                double len = Math.sqrt(lx * lx + ly * ly + lz * lz);
                if ((nx * lx + ny * ly + nz * lz) / len < MARGIN) {
                    continue;
                }
                double deepest = Double.NEGATIVE_INFINITY; // r - distance of centre from the segment
                for (double[] s : scene.spheres()) {
                    if (s == hitSphere) {
                        continue; // a ray leaving a sphere towards the light never re-enters it
                    }
                    deepest = Math.max(deepest, s[3] - segmentDistance(s, px, py, pz, lx, ly, lz));
                }
                if (deepest > MARGIN) {
                    kind[pixel] = SHADOW;
                    depth[pixel] = deepest;
                } else if (deepest < -MARGIN) {
                    kind[pixel] = LIT;
                    // moving the origin by h along n also lowers the light's height over the tangent plane by h
                    depth[pixel] = Math.min(-deepest, nx * lx + ny * ly + nz * lz);
                }
            }
        }
        return new ShadowTruth(kind, depth, hitPoint);
    }

    /** Distance of the sphere's centre from the line through e along unit d. */
    private static double lineDistance(double[] s, double ex, double ey, double ez, double[] d) {
        double fx = s[0] - ex, fy = s[1] - ey, fz = s[2] - ez;
        double along = fx * d[0] + fy * d[1] + fz * d[2];
        if (along < 0) {
            return Double.POSITIVE_INFINITY; // behind the camera
        }
        double qx = fx - along * d[0], qy = fy - along * d[1], qz = fz - along * d[2];
        return Math.sqrt(qx * qx + qy * qy + qz * qz);
    }

    /** Distance of the sphere's centre from the segment p .. p + l. */
    private static double segmentDistance(double[] s, double px, double py, double pz, double lx, double ly, double lz) {
        double fx = s[0] - px, fy = s[1] - py, fz = s[2] - pz;
        double u = Math.max(0, Math.min(1, (fx * lx + fy * ly + fz * lz) / (lx * lx + ly * ly + lz * lz)));
        double qx = fx - u * lx, qy = fy - u * ly, qz = fz - u * lz;
        return Math.sqrt(qx * qx + qy * qy + qz * qz);
    }
}
