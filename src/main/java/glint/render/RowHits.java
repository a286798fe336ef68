package glint.render;

import java.util.Arrays;

/**
 * What the camera rays of one tile row met, per worker, kept between the stages a row is traced in:
 * first every ray's nearest hit (found here, sphere by sphere, where it can be), then every hit's
 * surface and shading, with the matte hits set aside in slots of their own, then those lit
 * together light by light. Working a stage across the row keeps each loop short and its
 * iterations independent, so the square roots and divisions of neighbouring rays overlap instead
 * of waiting on one another. Stage 1's slot i belongs to camera ray i of the row ({@link
 * CameraRows}); the matte slots are indexed by the matte hit's place in the row, and {@link
 * #matteRays} names their camera rays. World space throughout. The arrays grow, never shrink.
 */
final class RowHits {

    // stage 1: the surface met (the other is -1; both -1 for a miss) and the distance to it
    int[] sphere = new int[0], plane = new int[0];
    double[] t = new double[0];

    // stage 2, per matte hit, in row order: the camera ray, the hit point on the surface, the
    // unit normal facing the ray, the offset of rays leaving the hit, the skip code of rays
    // leaving it on the ray's side, the material
    int[] matteRays = new int[0];
    int matteCount;
    double[] px = new double[0], py = new double[0], pz = new double[0];
    double[] nx = new double[0], ny = new double[0], nz = new double[0];
    double[] offset = new double[0];
    int[] skipNear = new int[0], material = new int[0];
    /** Stage 2's metal and glass hits, by camera ray, shaded after the row's matte hits are set aside. */
    int[] tracedRays = new int[0];

    // stage 3, per matte hit: the current light's sample (unit direction, distance, n.l and the
    // irradiance it brings, n.l included) and the radiance summed over the lights so far
    double[] toLightX = new double[0], toLightY = new double[0], toLightZ = new double[0];
    double[] lightDistance = new double[0], cosLight = new double[0];
    double[] lightR = new double[0], lightG = new double[0], lightB = new double[0];
    double[] sumR = new double[0], sumG = new double[0], sumB = new double[0];
    /** Per matte hit, 1 / its distance to the current point light. */
    double[] inverseDistance = new double[0];
    /**
     * Per matte hit, for a point light with {@link LightCones}: how far the direction from the light
     * to the hit falls inside the cone that comes nearest to holding it (below 0: in none).
     */
    double[] coneMargin = new double[0];
    /** The matte hits a sphere may shadow from the current light, set aside for the whole test. */
    int[] suspects = new int[0];

    /** Makes room for a row of {@code rays} camera rays. */
    void fit(int rays) {
        if (sphere.length >= rays) {
            return;
        }
        sphere = new int[rays];
        plane = new int[rays];
        t = new double[rays];
        px = new double[rays];
        py = new double[rays];
        pz = new double[rays];
        nx = new double[rays];
        ny = new double[rays];
        nz = new double[rays];
        offset = new double[rays];
        skipNear = new int[rays];
        material = new int[rays];
        matteRays = new int[rays];
        tracedRays = new int[rays];
        toLightX = new double[rays];
        toLightY = new double[rays];
        toLightZ = new double[rays];
        lightDistance = new double[rays];
        cosLight = new double[rays];
        lightR = new double[rays];
        lightG = new double[rays];
        lightB = new double[rays];
        sumR = new double[rays];
        sumG = new double[rays];
        sumB = new double[rays];
        inverseDistance = new double[rays];
        coneMargin = new double[rays];
        suspects = new int[rays];
    }

    // stage 1 sphere by sphere: the camera rays [sphereFirst[j], sphereEnd[j]) of the row are
    // tested against the row's j-th sphere ({@link EyeRays#rowSpheres})
    private int[] sphereFirst = new int[0], sphereEnd = new int[0];

    /**
     * Plans stage 1 sphere by sphere for camera rays [0, rays) of the row whose first pixel is image
     * x {@code rowX0}, {@code raysPerPixel} rays a pixel: each sphere the row can show ({@code eye},
     * aimed at the row) is to be tested against the rays of the pixels its screen range spans, and
     * a pixel more on each side. Returns the number of sphere tests that makes.
     */
    long planSphereBySphere(EyeRays eye, CameraRows rows, int rowX0, int raysPerPixel, int rays) {
        if (sphereFirst.length < eye.rowCount) {
            sphereFirst = new int[eye.rowSpheres.length];
            sphereEnd = new int[eye.rowSpheres.length];
        }
        int pixels = rays / raysPerPixel;
        long tests = 0;
        for (int j = 0; j < eye.rowCount; j++) {
            int i = eye.rowSpheres[j];
            sphereFirst[j] = raysPerPixel * pixelAtOrBefore(rows, eye.leftEdge(i), rowX0, pixels);
            sphereEnd[j] = raysPerPixel * (pixelAtOrAfter(rows, eye.rightEdge(i), rowX0, pixels) + 1);
            tests += sphereEnd[j] - sphereFirst[j];
        }
        return tests;
    }

    /**
     * Stage 1 sphere by sphere, as {@link #planSphereBySphere} planned it: the nearest hit of camera
     * rays [0, rays) of the row. Each sphere is tested against its rays, in the order the sweep
     * lists the spheres, then every ray against the planes. Each ray meets the tests {@link
     * RayCaster#nearestFromEye} gives it, in the same order, and at most a few more of spheres
     * whose range it lies outside of, which it cannot meet: it finds the same hit. (Where a pixel
     * can show more spheres than a ray tests one by one, {@code nearestFromEye} searches the
     * hierarchy instead: the same tests, in another order, so the same hit unless two surfaces
     * meet the ray at the very same distance.) A loop over one sphere's rays does the same
     * arithmetic for each, with no sweep and no call per ray.
     */
    void findFromEyeSphereBySphere(RenderScene s, EyeRays eye, CameraRows rows, int rays) {
        for (int ray = 0; ray < rays; ray++) {
            t[ray] = Intersect.MISS;
            sphere[ray] = -1;
            plane[ray] = -1;
        }
        for (int j = 0; j < eye.rowCount; j++) {
            keepNearerSphereHits(s, eye, rows, eye.rowSpheres[j], sphereFirst[j], sphereEnd[j]);
        }
        for (int p = 0; p < s.planeCount; p++) {
            keepNearerPlaneHits(s, eye, rows, p, rays);
        }
    }

    /** Camera rays [first, end) against sphere i: each keeps it where it meets it nearer than its hit so far. */
    private void keepNearerSphereHits(RenderScene s, EyeRays eye, CameraRows rows, int i, int first, int end) {
        double[] dirX = rows.dirX, dirY = rows.dirY, dirZ = rows.dirZ;
        double fx = eye.toCentre[3 * i], fy = eye.toCentre[3 * i + 1], fz = eye.toCentre[3 * i + 2], c = eye.c[i];
        double radius = s.spheres[4 * i + 3];
        for (int ray = first; ray < end; ray++) {
            double hitT = Intersect.sphereFrom(fx, fy, fz, c, radius, dirX[ray], dirY[ray], dirZ[ray], t[ray]);
            if (hitT < t[ray]) {
                t[ray] = hitT;
                sphere[ray] = i;
            }
        }
    }

    /** Camera rays [0, rays) against plane p, as {@link #keepNearerSphereHits}. */
    private void keepNearerPlaneHits(RenderScene s, EyeRays eye, CameraRows rows, int p, int rays) {
        double[] dirX = rows.dirX, dirY = rows.dirY, dirZ = rows.dirZ;
        int k = 4 * p;
        double nx = s.planes[k], ny = s.planes[k + 1], nz = s.planes[k + 2];
        double numerator = eye.planeNumerator[p];
        for (int ray = 0; ray < rays; ray++) {
            double hitT = Intersect.planeFrom(numerator, nx * dirX[ray] + ny * dirY[ray] + nz * dirZ[ray], t[ray]);
            if (hitT < t[ray]) {
                t[ray] = hitT;
                plane[ray] = p;
                sphere[ray] = -1;
            }
        }
    }

    /** A pixel of the row at or left of the one holding screen x (a pixel's margin on the safe side), in [0, pixels). */
    private static int pixelAtOrBefore(CameraRows rows, double screenX, int rowX0, int pixels) {
        double pixel = Math.floor(rows.pixelOf(screenX)) - rowX0 - 1;
        return pixel > 0 ? (int) Math.min(pixel, pixels - 1) : 0;
    }

    /** A pixel of the row at or right of the one holding screen x, in [0, pixels). */
    private static int pixelAtOrAfter(CameraRows rows, double screenX, int rowX0, int pixels) {
        double pixel = Math.floor(rows.pixelOf(screenX)) - rowX0 + 1;
        return pixel < pixels - 1 ? (int) Math.max(pixel, 0) : pixels - 1;
    }

    /** Stores the caster's last nearest-hit answer as ray i's hit. */
    void storeHit(int ray, RayCaster hit, boolean found) {
        sphere[ray] = found ? hit.hitSphere : -1;
        plane[ray] = found ? hit.hitPlane : -1;
        t[ray] = hit.hitT;
    }

    /**
     * Stage 3, the sample of a point light at (x, y, z) of power (powerR, powerG, powerB) at matte
     * hits [0, count): the arithmetic of {@code TracerWorker.lightAt}, written for the whole row so
     * that the light's terms stay in registers (a store to one double array could, for all the JIT
     * knows, change the light's). It goes in five loops, each without branches and small enough
     * for C2 to unroll, which it does only for a loop under {@code -XX:LoopUnrollLimit}, and so to
     * turn into SIMD instructions, four hits at a time; in one loop it stays scalar
     * (docs/benchmarks.md, {@code DividerBenchmark}). A hit at the light itself gets n.l = NaN
     * (0 times infinity), which the shadow stage passes over as it passes over n.l <= 0.
     */
    void samplePointLight(int count, double x, double y, double z, double powerR, double powerG, double powerB) {
        double[] px = this.px, py = this.py, pz = this.pz, inv = this.inverseDistance;
        for (int j = 0; j < count; j++) {
            double lx = x - px[j], ly = y - py[j], lz = z - pz[j];
            inv[j] = 1 / Math.sqrt(lx * lx + ly * ly + lz * lz);
        }
        double[] distance = this.lightDistance;
        for (int j = 0; j < count; j++) {
            double lx = x - px[j], ly = y - py[j], lz = z - pz[j];
            distance[j] = (lx * lx + ly * ly + lz * lz) * inv[j];
        }
        double[] ux = toLightX, uy = toLightY, uz = toLightZ;
        for (int j = 0; j < count; j++) {
            ux[j] = (x - px[j]) * inv[j];
            uy[j] = (y - py[j]) * inv[j];
            uz[j] = (z - pz[j]) * inv[j];
        }
        double[] nx = this.nx, ny = this.ny, nz = this.nz, cos = this.cosLight;
        for (int j = 0; j < count; j++) {
            cos[j] = ux[j] * nx[j] + uy[j] * ny[j] + uz[j] * nz[j];
        }
        double[] r = lightR, g = lightG, b = lightB;
        for (int j = 0; j < count; j++) {
            double scale = inv[j] * inv[j], c = cos[j];
            r[j] = powerR * scale * c;
            g[j] = powerG * scale * c;
            b[j] = powerB * scale * c;
        }
    }

    /**
     * Stage 3, for a point light's cones, after its samples: at each matte hit [0, count), the
     * largest over the cones of -(u . axis) - cos(half-angle), u the unit direction to the light.
     * It is below 0 exactly where {@link LightCones#holds} holds for no cone (x >= c and x - c >= 0
     * agree in floating point), so a hit there needs no cone tested. One loop per cone, each
     * branch-free and small, which the JIT turns into SIMD instructions as it does the samples'.
     */
    void coneMargins(int count, LightCones cones) {
        double[] margin = coneMargin, ux = toLightX, uy = toLightY, uz = toLightZ, axes = cones.cones;
        Arrays.fill(margin, 0, count, Double.NEGATIVE_INFINITY);
        for (int i = 0, n = cones.count; i < n; i++) {
            int k = 4 * i;
            double ax = axes[k], ay = axes[k + 1], az = axes[k + 2], cos = axes[k + 3];
            for (int j = 0; j < count; j++) {
                margin[j] = Math.max(margin[j], -(ux[j] * ax + uy[j] * ay + uz[j] * az) - cos);
            }
        }
    }

    /**
     * Stage 3, the sample of a directional light towards unit direction (x, y, z) (from the surface)
     * of irradiance (powerR, powerG, powerB) at matte hits [0, count), as {@link #samplePointLight}.
     */
    void sampleDirectionalLight(int count, double x, double y, double z, double powerR, double powerG,
                                double powerB) {
        for (int j = 0; j < count; j++) {
            double cos = x * nx[j] + y * ny[j] + z * nz[j];
            cosLight[j] = cos;
            toLightX[j] = x;
            toLightY[j] = y;
            toLightZ[j] = z;
            lightDistance[j] = Double.POSITIVE_INFINITY;
            lightR[j] = powerR * cos;
            lightG[j] = powerG * cos;
            lightB[j] = powerB * cos;
        }
    }
}
