package glint.accel;

import glint.geometry.Primitives;
import glint.geometry.PlaneKind;
import glint.geometry.PrimitiveKind;
import glint.geometry.SphereKind;
import glint.geometry.Intersect;
import glint.geometry.Hit;
import glint.geometry.DiscKind;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The hierarchy finds what testing every primitive finds: the same nearest hit, the same transmittance. */
class AggregateTest {

    private static final long SEED = 20_261_201L;

    @Test
    void theHierarchyAgreesWithBruteForceOnRandomScenes() {
        SplittableRandom random = new SplittableRandom(SEED);
        for (int scene = 0; scene < 40; scene++) {
            Primitives primitives = randomScene(random, 1 + random.nextInt(300), random.nextInt(3));
            compare(primitives, new Bvh(primitives, 1 + random.nextInt(6)), new FlatList(primitives), random, 2_000);
        }
    }

    @Test
    void aHitNamesItsKindAndIndex() {
        Primitives primitives = new Primitives(List.of(new SphereKind(new double[] {0, 0, 5, 1, 0, 0, 10, 1}),
                new PlaneKind(new double[] {0, 0, -1, -20})));
        Hit hit = new Hit();
        FlatList list = new FlatList(primitives);
        assertTrue(list.nearest(0, 0, 0, 0, 0, 1, Intersect.MISS, Hit.NONE, Hit.NONE, hit, list.newStack()));
        assertEquals(0, hit.kind);
        assertEquals(0, hit.index);
        assertEquals(4, hit.t, 1e-15);
        assertTrue(list.nearest(0, 0, 0, 0, 0, 1, Intersect.MISS, 0, Hit.NONE, hit, list.newStack()), "skipping sphere 0");
        assertEquals(1, hit.index);
        assertEquals(9, hit.t, 1e-15);
        assertTrue(list.nearest(0, 0, 12, 0, 0, 1, Intersect.MISS, Hit.NONE, Hit.NONE, hit, list.newStack()));
        assertEquals(1, hit.kind, "the plane z = 20");
        assertEquals(0, hit.index);
        assertEquals(2, hit.primitive);
        primitives.describe(hit, 0, 0, 12, 0, 0, 1);
        assertEquals(20, hit.pz, 0);
        assertEquals(-1, hit.nz, 0);
    }

    @Test
    void spheresAtExponentiallySpreadPlacesBuildADeepTreeItsStackHolds() {
        // 600 spheres at x = -2^i (i mod 60): a tree far deeper than a balanced one
        double[] spheres = new double[4 * 600];
        for (int i = 0; i < 600; i++) {
            spheres[4 * i] = -Math.pow(2, i % 60);
            spheres[4 * i + 3] = 0.25 + (i / 60) * 0.01;
        }
        Primitives primitives = new Primitives(List.of(new SphereKind(spheres)));
        Bvh bvh = new Bvh(primitives, 4);
        SplittableRandom random = new SplittableRandom(SEED + 1);
        FlatList list = new FlatList(primitives);
        Hit a = new Hit(), b = new Hit();
        for (int i = 0; i < 2_000; i++) {
            int target = random.nextInt(600);
            double ox = spheres[4 * target] + random.nextDouble(-2, 2), oy = 3, oz = random.nextDouble(-2, 2);
            double[] d = unit(random.nextDouble(-1, 1), -1, random.nextDouble(-0.2, 0.2));
            boolean foundA = bvh.nearest(ox, oy, oz, d[0], d[1], d[2], Intersect.MISS, Hit.NONE, Hit.NONE, a, bvh.newStack());
            boolean foundB = list.nearest(ox, oy, oz, d[0], d[1], d[2], Intersect.MISS, Hit.NONE, Hit.NONE, b, list.newStack());
            assertEquals(foundB, foundA);
            if (foundB) {
                assertEquals(b.t, a.t, 0);
                assertEquals(b.primitive, a.primitive);
            }
        }
    }

    @Test
    void aShapeKindAddedOutsideTheRendererIsSearchedLikeTheOthers() {
        SplittableRandom random = new SplittableRandom(SEED + 2);
        for (int scene = 0; scene < 10; scene++) {
            List<PrimitiveKind> kinds = new ArrayList<>(randomScene(random, 50, 1).kinds());
            double[] discs = new double[7 * 40];
            for (int i = 0; i < 40; i++) {
                double[] n = unit(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
                double[] c = {random.nextDouble(-10, 10), random.nextDouble(-10, 10), random.nextDouble(-10, 10)};
                System.arraycopy(c, 0, discs, 7 * i, 3);
                System.arraycopy(n, 0, discs, 7 * i + 3, 3);
                discs[7 * i + 6] = random.nextDouble(0.1, 2);
            }
            kinds.add(new DiscKind(discs));
            Primitives primitives = new Primitives(kinds);
            compare(primitives, new Bvh(primitives, 4), new FlatList(primitives), random, 2_000);
        }
    }

    @Test
    void aSphereIsEmptyExactlyWhenNoOtherPrimitiveReachesIntoIt() {
        SplittableRandom random = new SplittableRandom(SEED + 3);
        for (int scene = 0; scene < 30; scene++) {
            Primitives primitives = randomScene(random, 2 + random.nextInt(200), random.nextInt(3));
            boolean[] empty = EmptyInteriors.findEmpty(primitives);
            PrimitiveKind spheres = primitives.kind(0), planes = primitives.kind(1);
            double[] ball = new double[4];
            for (int a = 0; a < spheres.count(); a++) {
                spheres.boundingBall(a, ball);
                boolean reached = false;
                for (int b = 0; b < spheres.count(); b++) {
                    reached |= b != a && spheres.reachesInto(b, ball[0], ball[1], ball[2], ball[3]);
                }
                for (int b = 0; b < planes.count(); b++) {
                    reached |= planes.reachesInto(b, ball[0], ball[1], ball[2], ball[3]);
                }
                assertEquals(!reached, empty[a], "scene " + scene + ", sphere " + a);
            }
            for (int b = 0; b < planes.count(); b++) {
                assertEquals(false, empty[spheres.count() + b], "a plane has no inside");
            }
        }
    }

    /**
     * Rays sent into an empty sphere as a surface sends them: from the point on the line through
     * the centre at offset {@code offset} inside the surface point, towards the inside. An offset
     * above the diameter puts the origin past the sphere, where the filter must search as usual.
     */
    @Test
    void aRaySentIntoAnEmptySphereMeetsWhatTheFullSearchMeets() {
        SplittableRandom random = new SplittableRandom(SEED + 4);
        Hit a = new Hit(), b = new Hit();
        int inside = 0, pastIt = 0;
        for (int scene = 0; scene < 30; scene++) {
            Primitives primitives = randomScene(random, 2 + random.nextInt(100), 1 + random.nextInt(2));
            Aggregate filtered = EmptyInteriors.around(new FlatList(primitives));
            FlatList truth = new FlatList(primitives);
            TraversalStack stack = truth.newStack();
            PrimitiveKind spheres = primitives.kind(0);
            double[] ball = new double[4];
            for (int i = 0; i < 200; i++) {
                int sphere = random.nextInt(spheres.count());
                int hint = sphere; // spheres are kind 0, numbered first
                if (!filtered.emptyInside(hint)) {
                    continue;
                }
                spheres.boundingBall(sphere, ball);
                double[] n = unit(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
                double offset = ball[3] * random.nextDouble(0, 3);
                double fromCentre = ball[3] - offset;
                double ox = ball[0] + fromCentre * n[0], oy = ball[1] + fromCentre * n[1], oz = ball[2] + fromCentre * n[2];
                double[] d = unit(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
                double along = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
                if (along > 0) { // towards the inside of the surface point, as refracted and reflected rays go
                    d[0] = -d[0];
                    d[1] = -d[1];
                    d[2] = -d[2];
                }
                boolean found = truth.nearest(ox, oy, oz, d[0], d[1], d[2], Intersect.MISS, Hit.NONE, Hit.NONE, b, stack);
                assertEquals(found, filtered.nearest(ox, oy, oz, d[0], d[1], d[2], Intersect.MISS, Hit.NONE, hint, a,
                        stack));
                if (found) {
                    assertEquals(b.primitive, a.primitive);
                    assertEquals(b.t, a.t, 0);
                }
                if (offset < 1.999 * ball[3]) {
                    inside++;
                } else if (offset > 2.001 * ball[3]) {
                    pastIt++;
                }
            }
        }
        assertTrue(inside > 500 && pastIt > 200, "rays from inside: " + inside + ", from past the sphere: " + pastIt);
    }

    /**
     * Rays leaving a sphere on its outer side, as a surface sends them: from a point just off its
     * surface (0 to 1e-6 of max(1, |p|) outside), outwards or inwards along a tangent (grazing
     * the sphere's other side is left to the skip), skipping it; through the cells of
     * {@link LeavingCells} they meet what testing every primitive meets.
     */
    @Test
    void aRayLeavingASphereMeetsThroughItsCellsWhatBruteForceMeets() {
        SplittableRandom random = new SplittableRandom(SEED + 6);
        Hit a = new Hit(), b = new Hit();
        int throughCells = 0;
        for (int scene = 0; scene < 40; scene++) {
            int count = 1 + random.nextInt(scene % 4 == 0 ? 300 : 40);
            Primitives primitives = randomScene(random, count, random.nextInt(3));
            FlatList truth = new FlatList(primitives);
            Aggregate cells = LeavingCells.around(truth);
            TraversalStack stack = truth.newStack();
            PrimitiveKind spheres = primitives.kind(0);
            double[] ball = new double[4];
            double[] pass = passes(random, primitives.count());
            for (int i = 0; i < 2_000; i++) {
                int sphere = random.nextInt(spheres.count());
                int skip = sphere; // spheres are kind 0, numbered first
                spheres.boundingBall(sphere, ball);
                double[] n = unit(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
                double[] p = {ball[0] + ball[3] * n[0], ball[1] + ball[3] * n[1], ball[2] + ball[3] * n[2]};
                double off = random.nextDouble(0, 1e-6) * Math.max(1, Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
                double ox = p[0] + off * n[0], oy = p[1] + off * n[1], oz = p[2] + off * n[2];
                double[] d = unit(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
                double along = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
                if (i % 4 == 0) { // along the tangent plane, tilted a little inwards
                    double tilt = random.nextDouble(0, 1e-3);
                    d = unit(d[0] - (along + tilt) * n[0], d[1] - (along + tilt) * n[1], d[2] - (along + tilt) * n[2]);
                } else if (along < 0) {
                    d = unit(d[0] - 2 * along * n[0], d[1] - 2 * along * n[1], d[2] - 2 * along * n[2]);
                }
                double tMax = i % 5 == 0 ? random.nextDouble(0.5, 30) : Intersect.MISS;
                boolean found = truth.nearest(ox, oy, oz, d[0], d[1], d[2], tMax, skip, Hit.NONE, b, stack);
                assertEquals(found, cells.nearest(ox, oy, oz, d[0], d[1], d[2], tMax, skip, Hit.NONE, a, stack),
                        "scene " + scene + ", ray " + i);
                if (found) {
                    assertEquals(b.primitive, a.primitive, "scene " + scene + ", ray " + i);
                    assertEquals(b.t, a.t, 0);
                    assertEquals(b.kind, a.kind);
                    assertEquals(b.index, a.index);
                }
                double passB = truth.transmittance(ox, oy, oz, d[0], d[1], d[2], tMax, skip, pass, stack);
                assertEquals(passB, cells.transmittance(ox, oy, oz, d[0], d[1], d[2], tMax, skip, pass, stack),
                        1e-15 * passB, "scene " + scene + ", ray " + i);
                if (cells instanceof LeavingCells c && c.usesCells(skip, ox, oy, oz, d[0], d[1], d[2])) {
                    throughCells++;
                }
            }
        }
        assertTrue(throughCells > 40_000, "rays through cells: " + throughCells);
    }

    /**
     * Shadow rays towards a point light as a surface sends them: from a random point on a sphere or
     * plane, offset along the normal facing the light, straight to the light, skipping the primitive
     * where a surface would. Through a light's cells (8, 16 or 32 a side, caps from 1, where most
     * cells overflow, to 40) the light passed is what testing every primitive passes: with the spawn
     * offset (answered from the cells), with an offset far beyond the reach (searched), with lights
     * inside a sphere, and for rays whose end is nowhere near the light.
     */
    @Test
    void aShadowRayThroughALightsCellsPassesWhatBruteForcePasses() {
        SplittableRandom random = new SplittableRandom(SEED + 7);
        int[] sides = {8, 16, 32};
        int throughCells = 0, offsetTooFar = 0, overflowing = 0, insideASphere = 0;
        Hit a = new Hit(), b = new Hit();
        for (int scene = 0; scene < 40; scene++) {
            Primitives primitives = randomScene(random, 1 + random.nextInt(scene % 4 == 0 ? 300 : 40),
                    1 + random.nextInt(2));
            FlatList truth = new FlatList(primitives);
            TraversalStack stack = truth.newStack();
            PrimitiveKind spheres = primitives.kind(0);
            double[] ball = new double[4];
            double[] pass = passes(random, primitives.count());
            for (int light = 0; light < 4; light++) {
                double[] l = {random.nextDouble(-15, 15), random.nextDouble(-15, 15), random.nextDouble(-15, 15)};
                if (light == 3) { // inside a sphere
                    spheres.boundingBall(random.nextInt(spheres.count()), ball);
                    double[] e = unit(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
                    double at = random.nextDouble(0, 0.99) * ball[3];
                    l = new double[] {ball[0] + at * e[0], ball[1] + at * e[1], ball[2] + at * e[2]};
                }
                int cap = random.nextInt(4) == 0 ? 1 + random.nextInt(3) : 1 + random.nextInt(40);
                Aggregate cells = LightCells.around(truth, l[0], l[1], l[2], sides[random.nextInt(3)], cap);
                double reach = AggregatePolicy.SPAWN_MARGIN * Math.max(1, Math.sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]));
                for (int i = 0; i < 500; i++) {
                    double[] p = new double[3], n = new double[3];
                    int skip = surfacePoint(random, primitives, l, p, n);
                    double lx = l[0] - p[0], ly = l[1] - p[1], lz = l[2] - p[2];
                    double tMax = Math.sqrt(lx * lx + ly * ly + lz * lz);
                    double[] d = {lx / tMax, ly / tMax, lz / tMax};
                    double epsilon = i % 10 == 0 ? random.nextDouble(1e-5, 1e-2) : random.nextDouble(0, 1e-8);
                    double off = epsilon * Math.max(1, Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
                    double ox = p[0] + off * n[0], oy = p[1] + off * n[1], oz = p[2] + off * n[2];
                    if (i % 25 == 0) { // any ray, its end anywhere
                        tMax = random.nextDouble(0.1, 40);
                        d = unit(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
                    }
                    double passB = truth.transmittance(ox, oy, oz, d[0], d[1], d[2], tMax, skip, pass, stack);
                    String what = "scene " + scene + ", light " + light + ", ray " + i;
                    assertEquals(passB, cells.transmittance(ox, oy, oz, d[0], d[1], d[2], tMax, skip, pass, stack),
                            1e-14 * passB, what);
                    boolean found = truth.nearest(ox, oy, oz, d[0], d[1], d[2], tMax, skip, Hit.NONE, b, stack);
                    assertEquals(found, cells.nearest(ox, oy, oz, d[0], d[1], d[2], tMax, skip, Hit.NONE, a, stack));
                    if (found) {
                        assertEquals(b.primitive, a.primitive, what);
                        assertEquals(b.t, a.t, 0, what);
                    }
                    double ex = ox + tMax * d[0] - l[0], ey = oy + tMax * d[1] - l[1], ez = oz + tMax * d[2] - l[2];
                    boolean withinReach = ex * ex + ey * ey + ez * ez <= reach * reach;
                    boolean used = cells instanceof LightCells c && c.usesCells(ox, oy, oz, d[0], d[1], d[2], tMax);
                    assertTrue(withinReach || !used, "a ray ending out of reach is searched: " + what);
                    throughCells += used ? 1 : 0;
                    offsetTooFar += off > 2 * reach && i % 25 != 0 ? 1 : 0;
                    overflowing += withinReach && !used ? 1 : 0;
                    insideASphere += light == 3 && used ? 1 : 0;
                }
            }
        }
        assertTrue(throughCells > 30_000 && offsetTooFar > 4_000 && overflowing > 5_000 && insideASphere > 5_000,
                "through cells " + throughCells + ", offset beyond reach " + offsetTooFar + ", in overflowing cells "
                        + overflowing + ", from a light inside a sphere " + insideASphere);
    }

    /**
     * A random point p on a random primitive of the scene lit by the light at l, its unit normal n
     * facing the light, and the primitive a shadow ray from it skips: a plane's always, a sphere's
     * when p is on its outer side ({@link Hit#NONE} from the inside of a sphere around the light).
     */
    private static int surfacePoint(SplittableRandom random, Primitives primitives, double[] l, double[] p,
                                    double[] n) {
        int q = random.nextInt(primitives.count());
        PrimitiveKind kind = primitives.kind(primitives.kindOf(q));
        int index = primitives.indexOf(q);
        double[] outward;
        if (kind instanceof SphereKind) {
            double[] ball = new double[4];
            kind.boundingBall(index, ball);
            outward = unit(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
            for (int k = 0; k < 3; k++) {
                p[k] = ball[k] + ball[3] * outward[k];
            }
        } else {
            Hit hit = new Hit(); // the point of the plane nearest a random point
            primitives.record(hit, q, 0);
            primitives.describe(hit, random.nextDouble(-15, 15), random.nextDouble(-15, 15), random.nextDouble(-15, 15),
                    1, 0, 0);
            p[0] = hit.px;
            p[1] = hit.py;
            p[2] = hit.pz;
            outward = new double[] {hit.nx, hit.ny, hit.nz};
        }
        double facing = (l[0] - p[0]) * outward[0] + (l[1] - p[1]) * outward[1] + (l[2] - p[2]) * outward[2];
        double sign = facing >= 0 ? 1 : -1;
        for (int k = 0; k < 3; k++) {
            n[k] = sign * outward[k];
        }
        return kind instanceof SphereKind && sign < 0 ? Hit.NONE : q;
    }

    @Test
    void raysInsideAFrustumFindAmongItsGatheredPrimitivesWhatTheSearchFinds() {
        SplittableRandom random = new SplittableRandom(SEED + 5);
        Hit b = new Hit();
        Candidates candidates = new Candidates();
        Frustum frustum = new Frustum();
        for (int scene = 0; scene < 30; scene++) {
            Primitives primitives = randomScene(random, 1 + random.nextInt(300), random.nextInt(3));
            FlatList truth = new FlatList(primitives);
            Aggregate gathering = scene % 2 == 0 ? truth : new Bvh(primitives, 4);
            TraversalStack stack = gathering.newStack();
            for (int f = 0; f < 20; f++) {
                double ax = random.nextDouble(-15, 15), ay = random.nextDouble(-15, 15), az = random.nextDouble(-15, 15);
                double[] axis = unit(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
                double[] u = unit(-axis[1], axis[0] + axis[2], -axis[1]);
                double[] v = {axis[1] * u[2] - axis[2] * u[1], axis[2] * u[0] - axis[0] * u[2], axis[0] * u[1] - axis[1] * u[0]};
                double width = random.nextDouble(1e-4, 0.5), height = random.nextDouble(1e-4, 0.5);
                double[] edges = new double[12];
                double[][] corners = {{-width, -height}, {width, -height}, {width, height}, {-width, height}};
                for (int e = 0; e < 4; e++) {
                    for (int k = 0; k < 3; k++) {
                        edges[3 * e + k] = axis[k] + corners[e][0] * u[k] + corners[e][1] * v[k];
                    }
                }
                frustum.set(ax, ay, az, edges);
                gathering.gather(frustum, candidates, stack);
                int rays = 50;
                double[] dx = new double[rays], dy = new double[rays], dz = new double[rays], nearestT = new double[rays];
                int[] nearestPrimitive = new int[rays];
                for (int i = 0; i < rays; i++) {
                    double s = random.nextDouble(-1, 1) * width, t = random.nextDouble(-1, 1) * height;
                    double[] d = unit(axis[0] + s * u[0] + t * v[0], axis[1] + s * u[1] + t * v[1],
                            axis[2] + s * u[2] + t * v[2]);
                    dx[i] = d[0];
                    dy[i] = d[1];
                    dz[i] = d[2];
                }
                candidates.nearestFromOrigin(primitives, ax, ay, az, dx, dy, dz, rays, nearestT, nearestPrimitive);
                for (int i = 0; i < rays; i++) {
                    boolean found = truth.nearest(ax, ay, az, dx[i], dy[i], dz[i], Intersect.MISS, Hit.NONE, Hit.NONE, b,
                            stack);
                    assertEquals(found ? b.primitive : Hit.NONE, nearestPrimitive[i]);
                    assertEquals(found ? b.t : Intersect.MISS, nearestT[i], 0);
                }
            }
        }
    }

    /** The fraction of light each primitive passes: none for a third of them, 0.1 to 1 for the rest. */
    private static double[] passes(SplittableRandom random, int count) {
        double[] pass = new double[count];
        for (int p = 0; p < count; p++) {
            pass[p] = random.nextInt(3) == 0 ? 0 : random.nextDouble(0.1, 1);
        }
        return pass;
    }

    /** Rays from random points and from random surface points, skipping the primitive left, in both aggregates. */
    private static void compare(Primitives primitives, Aggregate tested, Aggregate truth, SplittableRandom random,
                                int rays) {
        Hit a = new Hit(), b = new Hit();
        TraversalStack stackA = tested.newStack(), stackB = truth.newStack();
        double[] pass = passes(random, primitives.count());
        for (int i = 0; i < rays; i++) {
            double ox = random.nextDouble(-15, 15), oy = random.nextDouble(-15, 15), oz = random.nextDouble(-15, 15);
            double[] d = unit(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
            if (i % 7 == 0) {
                d[random.nextInt(3)] = 0; // axis-parallel slabs
                d = unit(d[0], d[1], d[2]);
            }
            double tMax = i % 3 == 0 ? random.nextDouble(0.5, 30) : Intersect.MISS;
            int skip = i % 2 == 0 || primitives.count() == 0 ? Hit.NONE : random.nextInt(primitives.count());
            boolean foundA = tested.nearest(ox, oy, oz, d[0], d[1], d[2], tMax, skip, Hit.NONE, a, stackA);
            boolean foundB = truth.nearest(ox, oy, oz, d[0], d[1], d[2], tMax, skip, Hit.NONE, b, stackB);
            assertEquals(foundB, foundA, "ray " + i);
            if (foundB) {
                assertEquals(b.t, a.t, 0, "ray " + i);
                assertEquals(b.primitive, a.primitive, "ray " + i);
                assertEquals(b.kind, a.kind);
                assertEquals(b.index, a.index);
            }
            double passA = tested.transmittance(ox, oy, oz, d[0], d[1], d[2], tMax, skip, pass, stackA);
            double passB = truth.transmittance(ox, oy, oz, d[0], d[1], d[2], tMax, skip, pass, stackB);
            assertEquals(passB, passA, 1e-15 * passB, "ray " + i);
            assertTrue(passA >= 0 && passA <= 1);
        }
    }

    /** Random spheres (radius 0.05 to 3, a few of them huge) and planes. */
    private static Primitives randomScene(SplittableRandom random, int spheres, int planes) {
        double[] s = new double[4 * spheres];
        for (int i = 0; i < spheres; i++) {
            s[4 * i] = random.nextDouble(-12, 12);
            s[4 * i + 1] = random.nextDouble(-12, 12);
            s[4 * i + 2] = random.nextDouble(-12, 12);
            s[4 * i + 3] = random.nextInt(50) == 0 ? random.nextDouble(5, 40) : random.nextDouble(0.05, 3);
        }
        double[] p = new double[4 * planes];
        for (int i = 0; i < planes; i++) {
            double[] n = unit(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
            System.arraycopy(n, 0, p, 4 * i, 3);
            p[4 * i + 3] = random.nextDouble(-20, 20);
        }
        return new Primitives(List.of(new SphereKind(s), new PlaneKind(p)));
    }

    private static double[] unit(double x, double y, double z) {
        double length = Math.sqrt(x * x + y * y + z * z);
        if (length == 0) {
            return new double[] {0, 0, 1};
        }
        return new double[] {x / length, y / length, z / length};
    }
}
