package glint.render;

/**
 * Finds what a ray meets in a compiled scene: the nearest hit, or any hit before a distance
 * (shadow rays). Spheres are searched through the scene's {@link SphereBvh} when it has one,
 * otherwise one by one; planes always one by one. Per worker: holds the last hit and a traversal
 * stack, and allocates nothing per ray.
 */
final class RayCaster {

    /** Distance to the last nearest hit. */
    double hitT;
    /** The sphere of the last nearest hit, or -1. */
    int hitSphere;
    /** The plane of the last nearest hit, or -1. */
    int hitPlane;

    /** Rays cast so far (nearest and shadow queries), for rays-per-second figures. */
    long rays;

    /** Nodes a traversal will visit later; grown to the deepest hierarchy seen. */
    private int[] stack = new int[64];
    /** Where the ray enters the box of each node on the nearest-hit stack, found when it was pushed. */
    private double[] stackEntry = new double[64];

    /** The surface the current query ignores (see {@link #surfaceId}); 0 = none. */
    private int skip;

    /**
     * The {@code skip} code of a ray that starts inside sphere i, leaving it on its inner side: it
     * skips nothing, and when the sphere is empty only that sphere needs testing.
     */
    static int insideOf(int sphere) {
        return INSIDE_BASE + sphere;
    }

    /** The sphere a ray with this skip code starts inside of (see {@link #insideOf}), or -1. */
    static int sphereInside(int skipCode) {
        return skipCode < INSIDE_END && skipCode >= INSIDE_BASE ? skipCode - INSIDE_BASE : -1;
    }

    private static final int INSIDE_BASE = Integer.MIN_VALUE + 1;
    /** Codes below this are {@link #insideOf} codes (or the camera's); sphere counts stay far below 2^30. */
    private static final int INSIDE_END = Integer.MIN_VALUE / 2;

    /** The surface a query with this skip code leaves out: 0 (none) for a ray inside a sphere. */
    private static int skipped(int skipCode) {
        return skipCode < INSIDE_END ? 0 : skipCode;
    }

    /**
     * A surface's id for {@code skip}: sphere i is i + 1, plane j is -(j + 1). A ray leaving a
     * plane, or leaving a sphere on its outer side, cannot meet that surface again (both are
     * convex), so it is left out of the ray's tests: no self-intersection at any scale.
     */
    static int surfaceId(int sphere, int plane) {
        return sphere >= 0 ? sphere + 1 : -(plane + 1);
    }

    /**
     * The skip code of rays leaving a hit on the side the ray came from ({@code entering}: the
     * ray met the front, outer side): they leave out the surface itself, or, spawned inside a
     * sphere, say so and need test only that sphere when nothing else reaches into it.
     */
    static int skipNear(int sphere, int plane, boolean entering) {
        return plane >= 0 || entering ? surfaceId(sphere, plane) : insideOf(sphere);
    }

    /** The skip code of rays passing through a hit to the surface's other side. */
    static int skipFar(int sphere, int plane, boolean entering) {
        return plane >= 0 || !entering ? surfaceId(sphere, plane) : insideOf(sphere);
    }

    /**
     * {@code n}, which the caller knows is at most {@code most} (a small constant), written so that
     * the JIT knows it too. C2 keeps a safepoint poll in a loop counted by an int and wraps the loop
     * in an outer one, strip-mined, unless the types of its bounds show it runs at most
     * {@code -XX:LoopStripMiningIterShortLoop} (100) times. Set up on every entry, that outer loop
     * costs more instructions than the one to four tests of a small scene's loops over its planes,
     * cones or spheres (docs/benchmarks.md, "Short loops").
     */
    static int few(int n, int most) {
        return Math.min(n, most);
    }

    /**
     * The planes a loop over them tests in a loop the JIT knows is short ({@link #few}); the rest,
     * in scenes of more, go in a second loop.
     */
    static final int FEW_PLANES = 8;

    /** Nearest hit along the ray; sets hitT and hitSphere or hitPlane (the other is -1). */
    boolean nearest(RenderScene s, double ox, double oy, double oz, double dx, double dy, double dz, int skipCode) {
        rays++;
        hitT = Intersect.MISS;
        hitSphere = -1;
        hitPlane = -1;
        int inside = sphereInside(skipCode);
        if (inside >= 0 && leavesEmptySphere(s, inside, ox, oy, oz, dx, dy, dz)) {
            return true;
        }
        skip = skipped(skipCode);
        NeighbourCells around = skip > 0 ? s.neighbours[skip - 1] : null;
        if (around != null) {
            // leaving a sphere on its outer side: the planes, then the spheres listed for its direction
            nearestPlane(s, ox, oy, oz, dx, dy, dz);
            nearestListedSphere(s, around, ox, oy, oz, dx, dy, dz);
        } else if (s.bvh == null) {
            // without a hierarchy a scene has at most BVH_MIN_SPHERES spheres
            nearestSphereIn(s, 0, few(s.sphereCount, RenderScene.BVH_MIN_SPHERES), ox, oy, oz, dx, dy, dz);
            nearestPlane(s, ox, oy, oz, dx, dy, dz);
        } else {
            // the planes first: their distance bounds the search of the hierarchy
            nearestPlane(s, ox, oy, oz, dx, dy, dz);
            nearestSphereInBvh(s, ox, oy, oz, dx, dy, dz);
        }
        return hitT < Intersect.MISS;
    }

    private void nearestPlane(RenderScene s, double ox, double oy, double oz, double dx, double dy, double dz) {
        int n = s.planeCount;
        for (int i = 0, few = few(n, FEW_PLANES); i < few; i++) {
            keepPlaneIfNearer(s.planes, i, ox, oy, oz, dx, dy, dz);
        }
        for (int i = FEW_PLANES; i < n; i++) {
            keepPlaneIfNearer(s.planes, i, ox, oy, oz, dx, dy, dz);
        }
    }

    /** Tests plane i unless the query skips it; makes it the hit when the ray meets it nearer than the hit so far. */
    private void keepPlaneIfNearer(double[] planes, int i, double ox, double oy, double oz,
                                   double dx, double dy, double dz) {
        if (-(i + 1) == skip) {
            return;
        }
        int k = 4 * i;
        keepIfNearer(Intersect.planeBefore(planes[k], planes[k + 1], planes[k + 2], planes[k + 3],
                ox, oy, oz, dx, dy, dz, hitT), -1, i);
    }

    /**
     * For a ray inside sphere i: when nothing else reaches into it, sets the hit where the ray
     * leaves it and returns true; otherwise (or should rounding put the origin outside) false.
     */
    private boolean leavesEmptySphere(RenderScene s, int i, double ox, double oy, double oz,
                                      double dx, double dy, double dz) {
        if (!s.sphereIsEmpty[i]) {
            return false;
        }
        int k = 4 * i;
        double t = Intersect.sphereBefore(s.spheres[k], s.spheres[k + 1], s.spheres[k + 2], s.spheres[k + 3],
                ox, oy, oz, dx, dy, dz, Intersect.MISS);
        if (t == Intersect.MISS) {
            return false;
        }
        hitT = t;
        hitSphere = i;
        return true;
    }

    /** The nearest of spheres [first, first + count), count typed as few ({@link #few}). */
    private void nearestSphereIn(RenderScene s, int first, int count,
                                 double ox, double oy, double oz, double dx, double dy, double dz) {
        double[] spheres = s.spheres;
        for (int j = 0; j < count; j++) {
            int i = first + j;
            if (i + 1 != skip) {
                keepIfNearer(spheres, i, ox, oy, oz, dx, dy, dz);
            }
        }
    }

    /** Tests sphere i; makes it the hit when the ray meets it nearer than the hit found so far. */
    private void keepIfNearer(double[] spheres, int i, double ox, double oy, double oz, double dx, double dy, double dz) {
        int k = 4 * i;
        keepIfNearer(Intersect.sphereBefore(spheres[k], spheres[k + 1], spheres[k + 2], spheres[k + 3],
                ox, oy, oz, dx, dy, dz, hitT), i, -1);
    }

    /** Makes the surface met at distance t (a sphere or a plane, the other -1) the hit when t is nearer than the hit so far. */
    private void keepIfNearer(double t, int sphere, int plane) {
        if (t < hitT) {
            hitT = t;
            hitSphere = sphere;
            hitPlane = plane;
        }
    }

    /**
     * The nearest of the spheres the cells list for direction d, nearest first: stops at the first
     * that no ray from within the cells' reach can meet before the hit found so far.
     */
    private void nearestListedSphere(RenderScene s, NeighbourCells around, double ox, double oy, double oz,
                                     double dx, double dy, double dz) {
        double[] spheres = s.spheres, near = around.cellNear;
        int[] list = around.cellSpheres;
        int cell = around.cell(dx, dy, dz);
        for (int j = around.cellStart[cell], end = around.cellStart[cell + 1]; j < end && near[j] < hitT; j++) {
            keepIfNearer(spheres, list[j], ox, oy, oz, dx, dy, dz);
        }
    }

    private void nearestSphereInBvh(RenderScene s, double ox, double oy, double oz,
                                    double dx, double dy, double dz) {
        SphereBvh bvh = s.bvh;
        double[] bounds = bvh.bounds;
        int[] links = bvh.links;
        fitStack(bvh);
        double ix = 1 / nonZero(dx), iy = 1 / nonZero(dy), iz = 1 / nonZero(dz);
        if (boxEntry(bounds, 0, ox, oy, oz, ix, iy, iz) >= hitT) {
            return;
        }
        int node = 0;
        int top = 0;
        while (true) {
            int link = links[2 * node];
            int count = links[2 * node + 1];
            if (count > 0) {
                nearestSphereIn(s, link, few(count, SphereBvh.LEAF_SIZE), ox, oy, oz, dx, dy, dz);
            } else {
                double left = boxEntry(bounds, link, ox, oy, oz, ix, iy, iz);
                double right = boxEntry(bounds, link + 1, ox, oy, oz, ix, iy, iz);
                boolean hitsLeft = left < hitT, hitsRight = right < hitT;
                if (hitsLeft && hitsRight) {
                    // go on with the nearer child; the farther waits on the stack
                    boolean leftFirst = left <= right;
                    stack[top] = leftFirst ? link + 1 : link;
                    stackEntry[top++] = leftFirst ? right : left;
                    node = leftFirst ? link : link + 1;
                    continue;
                }
                if (hitsLeft || hitsRight) {
                    node = hitsLeft ? link : link + 1;
                    continue;
                }
            }
            // a nearer hit may have been found since a node was pushed
            do {
                if (top == 0) {
                    return;
                }
                node = stack[--top];
            } while (stackEntry[top] >= hitT);
        }
    }

    /** The camera rays' shared terms and the spheres each pixel can show. */
    final EyeRays eye = new EyeRays();

    /**
     * A camera ray whose pixel can show more spheres than this searches the hierarchy instead,
     * where the scene has one: past this, a sphere test each costs more than the search.
     */
    static final int MOST_SPHERES_SWEPT = 12;

    // the camera-ray terms for the packet path ({@link CameraPackets}), valid for the current row
    double[] eyeToCentre() {
        return eye.toCentre;
    }

    double[] eyeC() {
        return eye.c;
    }

    double[] eyePlaneNumerator() {
        return eye.planeNumerator;
    }

    int[] eyeCandidates() {
        return eye.rowSpheres;
    }

    int eyeCandidateCount() {
        return eye.rowCount;
    }

    /**
     * {@link #nearest} for a camera ray: from the eye, through the pixel {@link EyeRays#aimPixel}
     * was last given.
     */
    boolean nearestFromEye(RenderScene s, double dx, double dy, double dz) {
        EyeRays e = eye;
        if (e.pixelCount > MOST_SPHERES_SWEPT && s.bvh != null) {
            return nearestFromEyeInBvh(s, dx, dy, dz);
        }
        rays++;
        hitT = Intersect.MISS;
        hitSphere = -1;
        hitPlane = -1;
        double[] spheres = s.spheres, toCentre = e.toCentre, c = e.c;
        int[] candidates = e.pixelSpheres;
        for (int j = 0, n = e.pixelCount; j < n; j++) {
            int i = candidates[j];
            keepIfNearer(Intersect.sphereFrom(toCentre[3 * i], toCentre[3 * i + 1], toCentre[3 * i + 2],
                    c[i], spheres[4 * i + 3], dx, dy, dz, hitT), i, -1);
        }
        nearestPlaneFromEye(s, dx, dy, dz);
        return hitT < Intersect.MISS;
    }

    /** Kept apart so that {@link #nearestFromEye} stays small enough for the JIT to inline into the tracer. */
    private boolean nearestFromEyeInBvh(RenderScene s, double dx, double dy, double dz) {
        return nearest(s, s.camera.eyeX, s.camera.eyeY, s.camera.eyeZ, dx, dy, dz, 0);
    }

    private void nearestPlaneFromEye(RenderScene s, double dx, double dy, double dz) {
        double[] planes = s.planes, numerators = eye.planeNumerator;
        for (int i = 0, n = s.planeCount; i < n; i++) {
            int k = 4 * i;
            keepIfNearer(Intersect.planeFrom(numerators[i], planes[k] * dx + planes[k + 1] * dy + planes[k + 2] * dz,
                    hitT), -1, i);
        }
    }

    /** True when anything lies on the ray before distance tMax (any hit, not the nearest). */
    boolean occluded(RenderScene s, double ox, double oy, double oz, double dx, double dy, double dz, double tMax,
                     int skipCode) {
        return anyPlaneBefore(s, ox, oy, oz, dx, dy, dz, tMax, skipCode)
                || (s.bvh == null
                ? anySphereIn(s, 0, few(s.sphereCount, RenderScene.BVH_MIN_SPHERES), ox, oy, oz, dx, dy, dz, tMax)
                : anySphereInBvh(s, ox, oy, oz, dx, dy, dz, tMax));
    }

    /**
     * {@link #occluded} for a shadow ray towards light {@code light}, leaving from a point
     * {@code offset} from the surface: tests only the spheres whose {@link LightCones} hold its
     * direction, or those the light's {@link LightBuffer} lists for it, where it can.
     */
    boolean shadowed(RenderScene s, double ox, double oy, double oz, double dx, double dy, double dz, double tMax,
                     int skipCode, int light, double offset) {
        LightCones cones = s.lightCones[light];
        if (cones != null && offset <= cones.maxOffset) {
            return anyPlaneBefore(s, ox, oy, oz, dx, dy, dz, tMax, skipCode)
                    || anySphereInCone(s, cones, ox, oy, oz, dx, dy, dz, tMax);
        }
        LightBuffer buffer = s.lightBuffers[light];
        if (buffer == null || offset > buffer.maxOffset) {
            return occluded(s, ox, oy, oz, dx, dy, dz, tMax, skipCode);
        }
        int cell = buffer.cell(-dx, -dy, -dz);
        int first = buffer.cellStart[cell], end = buffer.cellStart[cell + 1];
        if (s.bvh != null && end - first > MOST_SPHERES_LISTED) {
            return occluded(s, ox, oy, oz, dx, dy, dz, tMax, skipCode);
        }
        return anyPlaneBefore(s, ox, oy, oz, dx, dy, dz, tMax, skipCode)
                || anyListedSphere(s, buffer.cellSpheres, first, end, ox, oy, oz, dx, dy, dz, tMax);
    }

    /**
     * Whether a sphere may lie on the shadow ray towards light {@code light} along unit d, leaving
     * from a point {@code offset} from the surface with skip code {@code skipCode}: false only where
     * the light's cones or buffer rule every sphere out (the sphere the ray leaves on its outer
     * side included), and then {@link #shadowed} is {@link #anyPlaneBefore}. Has no calls the JIT
     * would not inline, so that a loop over a row's shadow rays keeps its values in registers.
     */
    boolean sphereMayShadow(RenderScene s, double dx, double dy, double dz, int light, double offset, int skipCode) {
        LightCones cones = s.lightCones[light];
        if (cones != null && offset <= cones.maxOffset) {
            int left = skipped(skipCode) - 1; // the sphere left on its outer side, or below 0
            for (int i = 0, n = few(cones.count, LightCones.MOST_SPHERES); i < n; i++) {
                if (i != left && cones.holds(i, dx, dy, dz)) {
                    return true;
                }
            }
            return false;
        }
        LightBuffer buffer = s.lightBuffers[light];
        if (buffer == null || offset > buffer.maxOffset) {
            return s.sphereCount > 0;
        }
        int cell = buffer.cell(-dx, -dy, -dz);
        return buffer.cellStart[cell] != buffer.cellStart[cell + 1];
    }

    /**
     * Whether a plane lies on the ray before tMax (counted as a ray cast); sets {@link #skip} for
     * the sphere tests that follow.
     */
    boolean anyPlaneBefore(RenderScene s, double ox, double oy, double oz, double dx, double dy, double dz,
                           double tMax, int skipCode) {
        skip = skipped(skipCode);
        rays++;
        if (noPlaneToTest(s, skipCode)) {
            return false;
        }
        int n = s.planeCount;
        for (int i = 0, few = few(n, FEW_PLANES); i < few; i++) {
            if (planeBlocks(s.planes, i, ox, oy, oz, dx, dy, dz, tMax)) {
                return true;
            }
        }
        for (int i = FEW_PLANES; i < n; i++) {
            if (planeBlocks(s.planes, i, ox, oy, oz, dx, dy, dz, tMax)) {
                return true;
            }
        }
        return false;
    }

    /** Whether plane i, unless the query skips it, lies on the ray before tMax. */
    private boolean planeBlocks(double[] planes, int i, double ox, double oy, double oz, double dx, double dy,
                                double dz, double tMax) {
        int k = 4 * i;
        return -(i + 1) != skip && Intersect.planeBefore(planes[k], planes[k + 1], planes[k + 2], planes[k + 3],
                ox, oy, oz, dx, dy, dz, tMax) < tMax;
    }

    /**
     * Whether a ray with skip code {@code skipCode} has no plane to test: the scene has none, or only
     * the one the ray leaves (the floor of most scenes, whose hits make most of a frame's shadow
     * rays). Spares those rays the plane loop's setup.
     */
    static boolean noPlaneToTest(RenderScene s, int skipCode) {
        return s.planeCount == 0 || (s.planeCount == 1 && skipCode == ONLY_PLANE);
    }

    /** The skip code of a ray leaving plane 0. */
    private static final int ONLY_PLANE = -1;

    /**
     * A shadow ray whose light-buffer cell lists more spheres than this searches the hierarchy
     * instead, where the scene has one.
     */
    static final int MOST_SPHERES_LISTED = 12;

    /** Whether any of spheres list[first, end) lies on the ray before tMax. */
    private boolean anyListedSphere(RenderScene s, int[] list, int first, int end, double ox, double oy, double oz,
                                    double dx, double dy, double dz, double tMax) {
        for (int j = first; j < end; j++) {
            if (blocks(s, list[j], ox, oy, oz, dx, dy, dz, tMax)) {
                return true;
            }
        }
        return false;
    }

    /** Whether any sphere whose cone holds the ray's direction lies on the ray before tMax. */
    private boolean anySphereInCone(RenderScene s, LightCones cones, double ox, double oy, double oz,
                                    double dx, double dy, double dz, double tMax) {
        for (int i = 0, n = few(cones.count, LightCones.MOST_SPHERES); i < n; i++) {
            if (cones.holds(i, dx, dy, dz) && blocks(s, i, ox, oy, oz, dx, dy, dz, tMax)) {
                return true;
            }
        }
        return false;
    }

    /** Whether any of spheres [first, first + count), count typed as few ({@link #few}), lies on the ray before tMax. */
    private boolean anySphereIn(RenderScene s, int first, int count, double ox, double oy, double oz,
                                double dx, double dy, double dz, double tMax) {
        for (int j = 0; j < count; j++) {
            if (blocks(s, first + j, ox, oy, oz, dx, dy, dz, tMax)) {
                return true;
            }
        }
        return false;
    }

    /** Whether sphere i, unless the query skips it, lies on the ray before tMax. */
    private boolean blocks(RenderScene s, int i, double ox, double oy, double oz, double dx, double dy, double dz,
                           double tMax) {
        int k = 4 * i;
        double[] spheres = s.spheres;
        return i + 1 != skip && Intersect.sphereBefore(spheres[k], spheres[k + 1], spheres[k + 2], spheres[k + 3],
                ox, oy, oz, dx, dy, dz, tMax) < tMax;
    }

    /**
     * Makes room on the stack for a traversal of this hierarchy: it descends into one child and
     * keeps at most the other waiting, one node per level.
     */
    private void fitStack(SphereBvh bvh) {
        if (stack.length < bvh.depth) {
            stack = new int[bvh.depth];
            stackEntry = new double[bvh.depth];
        }
    }

    private boolean anySphereInBvh(RenderScene s, double ox, double oy, double oz,
                                   double dx, double dy, double dz, double tMax) {
        SphereBvh bvh = s.bvh;
        double[] bounds = bvh.bounds;
        int[] links = bvh.links;
        fitStack(bvh);
        double ix = 1 / nonZero(dx), iy = 1 / nonZero(dy), iz = 1 / nonZero(dz);
        if (boxEntry(bounds, 0, ox, oy, oz, ix, iy, iz) >= tMax) {
            return false;
        }
        int node = 0;
        int top = 0;
        while (true) {
            int link = links[2 * node];
            int count = links[2 * node + 1];
            if (count > 0) {
                if (anySphereIn(s, link, few(count, SphereBvh.LEAF_SIZE), ox, oy, oz, dx, dy, dz, tMax)) {
                    return true;
                }
            } else {
                boolean hitsLeft = boxEntry(bounds, link, ox, oy, oz, ix, iy, iz) < tMax;
                boolean hitsRight = boxEntry(bounds, link + 1, ox, oy, oz, ix, iy, iz) < tMax;
                if (hitsLeft) {
                    if (hitsRight) {
                        stack[top++] = link + 1;
                    }
                    node = link;
                    continue;
                }
                if (hitsRight) {
                    node = link + 1;
                    continue;
                }
            }
            if (top == 0) {
                return false;
            }
            node = stack[--top];
        }
    }

    /**
     * Phong shadows: the fraction of light passing to distance tMax, kt for each glass object
     * crossed, 0 at the first opaque one. Objects are visited one by one (the BVH finds nearest and
     * any hits; a product over all hits is rare enough to need neither).
     */
    double transmittance(RenderScene s, double ox, double oy, double oz, double dx, double dy, double dz,
                         double tMax, int skipCode) {
        int skipSurface = skipped(skipCode);
        rays++;
        double pass = 1;
        double[] planes = s.planes;
        for (int i = 0, n = s.planeCount; i < n && pass > 0; i++) {
            if (-(i + 1) == skipSurface) {
                continue;
            }
            int k = 4 * i;
            if (Intersect.planeBefore(planes[k], planes[k + 1], planes[k + 2], planes[k + 3],
                    ox, oy, oz, dx, dy, dz, tMax) < tMax) {
                pass *= s.shadowPass(s.planeMaterial[i]);
            }
        }
        double[] spheres = s.spheres;
        for (int i = 0, n = s.sphereCount; i < n && pass > 0; i++) {
            if (i + 1 == skipSurface) {
                continue;
            }
            int k = 4 * i;
            if (Intersect.sphereBefore(spheres[k], spheres[k + 1], spheres[k + 2], spheres[k + 3],
                    ox, oy, oz, dx, dy, dz, tMax) < tMax) {
                pass *= s.shadowPass(s.sphereMaterial[i]);
            }
        }
        return pass;
    }

    /**
     * Distance along the ray to where it enters the node's box (0 when it starts inside), or
     * {@link Intersect#MISS}. Slab test with precomputed reciprocal directions; zero direction
     * components are replaced by a tiny one first, so no 0 x infinity makes a NaN.
     */
    private static double boxEntry(double[] bounds, int node, double ox, double oy, double oz,
                                   double ix, double iy, double iz) {
        int b = 6 * node;
        double tx0 = (bounds[b] - ox) * ix, tx1 = (bounds[b + 3] - ox) * ix;
        double ty0 = (bounds[b + 1] - oy) * iy, ty1 = (bounds[b + 4] - oy) * iy;
        double tz0 = (bounds[b + 2] - oz) * iz, tz1 = (bounds[b + 5] - oz) * iz;
        double near = max(max(min(tx0, tx1), min(ty0, ty1)), max(min(tz0, tz1), 0));
        double far = min(min(max(tx0, tx1), max(ty0, ty1)), max(tz0, tz1));
        return near <= far * (1 + 2e-16 * 4) ? near : Intersect.MISS;
    }

    private static double nonZero(double component) {
        return component == 0 ? 1e-300 : component;
    }

    // plain comparisons: no NaN can reach them, so Math.min/max's NaN handling is not needed
    private static double min(double a, double b) {
        return a < b ? a : b;
    }

    private static double max(double a, double b) {
        return a > b ? a : b;
    }
}
