package glint.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.math.Vector3d;
import glint.recipe.Disc;
import glint.recipe.DiscType;
import glint.registry.PlaneType;
import glint.registry.Registry;
import glint.registry.ShapeType;
import glint.registry.SphereType;
import glint.scene.Plane;
import glint.scene.Shape;
import glint.scene.Sphere;
import glint.shading.Surface;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.TreeSet;
import java.util.function.Function;
import java.util.function.ToDoubleBiFunction;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * What every primitive kind promises the renderer, checked on seeded random primitives and rays for
 * each kind the registry knows (and the tests' disc, registered as its recipe does), as pbrt's shape
 * tests do: {@code intersect} agrees with a brute-force march; the hit's surface point lies on the
 * surface, within {@code bounds} (and, closed, within {@code boundingBall}), with a unit normal that
 * points outward; a ray spawned from the hit as the renderer spawns it ({@link Surface}: epsilon x
 * max(1, |p|) off the surface) never meets the surface again on the side it leaves; and
 * {@code reachesInto} answers true for every ball that holds a point of the primitive. A new kind
 * gets all of it by one entry in {@link #CASES}: how to make a random shape of it, and the distance
 * from a point to such a shape's surface.
 */
class PrimitiveKindContractTest {

    /** Every kind: the standard registry and the disc of the recipe tests. */
    private static final Registry REGISTRY = Registry.STANDARD.with(DiscType.TYPE);

    private static final List<KindCase<?>> CASES = List.of(
            new KindCase<>(SphereType.TYPE, random -> new Sphere(point(random, 5), 0.2 + 3 * random.nextDouble()),
                    (sphere, p) -> Math.abs(p.sub(sphere.center()).length() - sphere.radius())),
            new KindCase<>(PlaneType.TYPE, random -> new Plane(point(random, 5), direction(random)),
                    (plane, p) -> Math.abs(plane.normal().dot(p.sub(plane.point())))),
            new KindCase<>(DiscType.TYPE, random -> new Disc(point(random, 5), direction(random),
                    0.2 + 3 * random.nextDouble()), PrimitiveKindContractTest::discDistance));

    /** The renderer's default spawn offset factor. */
    private static final double EPSILON = 1e-9;
    /** How far rays are followed. */
    private static final double FAR = 1e3;
    private static final int PRIMITIVES = 6, RAYS_PER_PRIMITIVE = 300;

    /** A kind as the test makes it: random shapes of its type, and the exact distance to a shape's surface. */
    record KindCase<S extends Shape>(ShapeType<S> type, Function<Random, S> randomShape,
                                     ToDoubleBiFunction<S, Vector3d> distance) {

        /** Seeded random shapes of this type, compiled through the type's registration. */
        Primitives make(Random random, List<SurfaceDistance> distances) {
            List<S> shapes = new ArrayList<>();
            for (int i = 0; i < PRIMITIVES; i++) {
                S shape = randomShape.apply(random);
                shapes.add(shape);
                distances.add(p -> distance.applyAsDouble(shape, p));
            }
            return new Primitives(List.of(type.compile(shapes)));
        }

        @Override
        public String toString() {
            return type.name();
        }
    }

    /** The distance from a point to one primitive's surface. */
    interface SurfaceDistance {
        double at(Vector3d p);
    }

    static Stream<KindCase<?>> cases() {
        return CASES.stream();
    }

    @Test
    void everyRegisteredKindIsChecked() {
        TreeSet<String> registered = REGISTRY.shapes().stream().map(ShapeType::name)
                .collect(Collectors.toCollection(TreeSet::new));
        TreeSet<String> checked = CASES.stream().map(c -> c.type().name()).collect(Collectors.toCollection(TreeSet::new));
        assertEquals(registered, checked, "each registered kind needs an entry in CASES");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void keepsTheContractOnRandomPrimitivesAndRays(KindCase<?> kindCase) {
        Random random = new Random(4301 + kindCase.type().name().hashCode());
        List<SurfaceDistance> distances = new ArrayList<>();
        Primitives primitives = kindCase.make(random, distances);
        PrimitiveKind kind = primitives.kind(0);
        Checks checks = new Checks();
        for (int i = 0; i < kind.count(); i++) {
            List<Vector3d> points = new ArrayList<>(); // points of the primitive: its surface, and inside a closed one
            for (int ray = 0; ray < RAYS_PER_PRIMITIVE; ray++) {
                checkRay(primitives, i, distances.get(i), random, points, checks);
            }
            checkBalls(kind, i, points, random, checks);
        }
        // the checks above ran, and on enough cases to mean something
        assertTrue(checks.hits > 300, checks.hits + " hits");
        assertTrue(checks.misses > 50, checks.misses + " misses");
        assertTrue(checks.inconclusive * 100 < checks.hits + checks.misses, checks.inconclusive + " marches inconclusive");
        assertTrue(checks.spawned > 1000, checks.spawned + " spawned rays");
        assertTrue(checks.ballsHolding > 100, checks.ballsHolding + " balls holding a point");
        if (kind.closed()) {
            assertTrue(checks.entered > 100, checks.entered + " rays entering from outside");
            assertTrue(checks.chords > 100, checks.chords + " chords inside");
        }
    }

    /** How many cases each check met. */
    private static final class Checks {
        int hits, misses, inconclusive, spawned, entered, chords, ballsHolding;
    }

    /** One ray towards primitive i: its hit against the march, then the hit's surface and the rays spawned from it. */
    private static void checkRay(Primitives primitives, int i, SurfaceDistance distance, Random random,
                                 List<Vector3d> points, Checks checks) {
        PrimitiveKind kind = primitives.kind(0);
        Vector3d o = point(random, 12);
        if (distance.at(o) < 1e-3) {
            return;
        }
        Vector3d d = towards(kind, i, o, random);
        double t = kind.intersect(i, o.x(), o.y(), o.z(), d.x(), d.y(), d.z(), FAR);
        double marched = march(distance, o, d);
        if (Double.isNaN(marched)) {
            checks.inconclusive++;
            return;
        }
        if (marched == Intersect.MISS) {
            assertEquals(Intersect.MISS, t, () -> "the march finds no surface from " + o + " along " + d);
            checks.misses++;
            return;
        }
        assertTrue(Math.abs(t - marched) <= 1e-6 * (1 + marched),
                () -> "from " + o + " along " + d + ": intersect " + t + ", the march " + marched);
        checks.hits++;
        Hit hit = new Hit();
        primitives.record(hit, i, t);
        primitives.describe(hit, o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
        Vector3d p = new Vector3d(hit.px, hit.py, hit.pz), n = new Vector3d(hit.nx, hit.ny, hit.nz);
        checkSurfacePoint(kind, i, distance, p, n);
        points.add(p);
        if (kind.closed() && outsideBall(kind, i, o)) {
            assertTrue(d.dot(n) < 0, () -> "a ray from outside meets the outer side: normal " + n + " along " + d);
            checks.entered++;
        }
        checkTangent(primitives, i, o, d, hit, random);
        Surface s = new Surface();
        s.set(hit, o.x(), o.y(), o.z(), d.x(), d.y(), d.z(), EPSILON, 0, kind.closed());
        checkSpawned(primitives, i, distance, s, n, random, points, checks);
    }

    /** On the surface, in the box and the ball, its normal unit. */
    private static void checkSurfacePoint(PrimitiveKind kind, int i, SurfaceDistance distance, Vector3d p, Vector3d n) {
        assertEquals(1, n.length(), 1e-12, "a unit normal");
        assertTrue(distance.at(p) <= 1e-12 * (1 + p.length()), () -> p + " lies on the surface: " + distance.at(p) + " off");
        checkHeld(kind, i, p);
    }

    /** Point p of primitive i lies in its box, and for a closed kind in its bounding ball. */
    private static void checkHeld(PrimitiveKind kind, int i, Vector3d p) {
        double[] box = new double[6];
        kind.bounds(i, box, 0);
        double[] c = {p.x(), p.y(), p.z()};
        for (int axis = 0; axis < 3; axis++) {
            int a = axis;
            assertTrue(box[a] <= c[a] && c[a] <= box[3 + a], () -> p + " outside the bounds on axis " + a);
        }
        if (kind.closed()) {
            double[] ball = new double[4];
            kind.boundingBall(i, ball);
            double from = p.sub(new Vector3d(ball[0], ball[1], ball[2])).length();
            assertTrue(from <= ball[3] * (1 + 1e-12), () -> p + " outside the bounding ball by " + (from - ball[3]));
        }
    }

    /** The normal is the surface's: a hit a hair away along the surface lies in its tangent plane. */
    private static void checkTangent(Primitives primitives, int i, Vector3d o, Vector3d d, Hit hit, Random random) {
        double cos = Math.abs(d.x() * hit.nx + d.y() * hit.ny + d.z() * hit.nz);
        if (cos < 0.05) {
            return;
        }
        Vector3d nudged = d.add(direction(random).scale(1e-7)).normalize();
        PrimitiveKind kind = primitives.kind(0);
        double t = kind.intersect(i, o.x(), o.y(), o.z(), nudged.x(), nudged.y(), nudged.z(), FAR);
        if (t == Intersect.MISS) {
            return;
        }
        Vector3d step = o.add(nudged.scale(t)).sub(new Vector3d(hit.px, hit.py, hit.pz));
        double along = Math.abs(step.dot(new Vector3d(hit.nx, hit.ny, hit.nz))) / step.length();
        assertTrue(along < 1e-4, () -> "a step along the surface leaves its tangent plane by " + along);
    }

    /**
     * Rays spawned from the hit as the renderer spawns them: leaving on the outer side, and leaving
     * on the inner side of a flat kind, they never meet the primitive again; leaving into a closed
     * one, they meet its far side (against the march), leaving it outward.
     */
    private static void checkSpawned(Primitives primitives, int i, SurfaceDistance distance, Surface s,
                                     Vector3d outward, Random random, List<Vector3d> points, Checks checks) {
        PrimitiveKind kind = primitives.kind(0);
        // the renderer's origins: the side the ray came from (near), the other (far)
        Vector3d near = new Vector3d(s.nearX(), s.nearY(), s.nearZ()), far = new Vector3d(s.farX(), s.farY(), s.farZ());
        Vector3d outer = s.front ? near : far, inner = s.front ? far : near;
        for (int k = 0; k < 4; k++) {
            Vector3d out = hemisphere(outward, random);
            assertEquals(Intersect.MISS, kind.intersect(i, outer.x(), outer.y(), outer.z(), out.x(), out.y(), out.z(), FAR),
                    () -> "a ray leaving " + outer + " outward along " + out + " meets the surface it left");
            Vector3d in = hemisphere(outward.scale(-1), random);
            double t = kind.intersect(i, inner.x(), inner.y(), inner.z(), in.x(), in.y(), in.z(), FAR);
            checks.spawned += 2;
            if (!kind.closed()) {
                assertEquals(Intersect.MISS, t, () -> "a ray leaving " + inner + " along " + in + " meets the surface it left");
                continue;
            }
            if (-in.dot(outward) < 0.05) {
                continue; // a grazing chord: too short to tell from its start
            }
            assertTrue(t != Intersect.MISS && t > 1e3 * s.offset,
                    () -> "a ray into the closed primitive from " + inner + " along " + in + " meets it at t = " + t);
            double marched = march(distance, inner, in);
            assertTrue(Math.abs(t - marched) <= 1e-6 * (1 + marched), () -> "inside: intersect " + t + ", the march " + marched);
            Hit end = new Hit();
            primitives.record(end, i, t);
            primitives.describe(end, inner.x(), inner.y(), inner.z(), in.x(), in.y(), in.z());
            Vector3d endPoint = new Vector3d(end.px, end.py, end.pz), endNormal = new Vector3d(end.nx, end.ny, end.nz);
            checkSurfacePoint(kind, i, distance, endPoint, endNormal);
            assertTrue(in.dot(endNormal) > 0, () -> "a ray inside leaves through the outer side: normal " + endNormal);
            for (double f = 0.25; f < 1; f += 0.25) { // the chord's inside
                Vector3d q = inner.add(in.scale(f * t));
                checkHeld(kind, i, q);
                points.add(q);
            }
            points.add(endPoint);
            checks.chords++;
        }
    }

    /** Whether reachesInto answers true for random balls that hold one of the primitive's points. */
    private static void checkBalls(PrimitiveKind kind, int i, List<Vector3d> points, Random random, Checks checks) {
        if (points.isEmpty()) {
            return;
        }
        for (int b = 0; b < 200; b++) {
            Vector3d chosen = points.get(random.nextInt(points.size()));
            double reach = 0.01 + 2 * random.nextDouble();
            Vector3d centre = chosen.add(direction(random).scale(reach));
            double radius = reach * (0.5 + random.nextDouble());
            Vector3d held = null;
            for (Vector3d p : points) {
                if (p.sub(centre).length() < radius * (1 - 1e-9)) {
                    held = p;
                    break;
                }
            }
            boolean reaches = kind.reachesInto(i, centre.x(), centre.y(), centre.z(), radius);
            if (held != null) {
                Vector3d inside = held;
                assertTrue(reaches, () -> "the ball at " + centre + " of radius " + radius + " holds " + inside
                        + ", but reachesInto says no");
                checks.ballsHolding++;
            }
        }
    }

    /**
     * The brute force: marches from o along unit d, each step the distance to the surface (which no
     * step can cross), to where it is under 1e-10 (1 + |p|); {@link Intersect#MISS} past {@link #FAR},
     * NaN when a ray grazing the surface makes the march too slow to tell.
     */
    private static double march(SurfaceDistance distance, Vector3d o, Vector3d d) {
        double t = 0;
        for (int step = 0; step < 200_000; step++) {
            Vector3d p = o.add(d.scale(t));
            double gap = distance.at(p);
            if (gap < 1e-10 * (1 + p.length())) {
                return t;
            }
            t += gap;
            if (t >= FAR) {
                return Intersect.MISS;
            }
        }
        return Double.NaN;
    }

    /** A direction from o towards a point near primitive i (anywhere, for an unbounded one). */
    private static Vector3d towards(PrimitiveKind kind, int i, Vector3d o, Random random) {
        if (!kind.bounded(i)) {
            return direction(random);
        }
        double[] box = new double[6];
        kind.bounds(i, box, 0);
        Vector3d target = new Vector3d(between(random, box[0], box[3]), between(random, box[1], box[4]),
                between(random, box[2], box[5]));
        return target.sub(o).normalize();
    }

    /** A box 20 % wider than [low, high] on each side. */
    private static double between(Random random, double low, double high) {
        double margin = 0.2 * (high - low);
        return low - margin + (high - low + 2 * margin) * random.nextDouble();
    }

    private static boolean outsideBall(PrimitiveKind kind, int i, Vector3d o) {
        double[] ball = new double[4];
        kind.boundingBall(i, ball);
        return o.sub(new Vector3d(ball[0], ball[1], ball[2])).length() > ball[3];
    }

    /** The distance from p to a disc: to its plane within its radius, to its rim beyond. */
    private static double discDistance(Disc disc, Vector3d p) {
        Vector3d e = p.sub(disc.center());
        double height = e.dot(disc.normal());
        double across = e.sub(disc.normal().scale(height)).length();
        return across <= disc.radius() ? Math.abs(height) : Math.hypot(height, across - disc.radius());
    }

    private static Vector3d point(Random random, double half) {
        return new Vector3d(half * (2 * random.nextDouble() - 1), half * (2 * random.nextDouble() - 1),
                half * (2 * random.nextDouble() - 1));
    }

    private static Vector3d direction(Random random) {
        while (true) {
            Vector3d v = point(random, 1);
            double length = v.length();
            if (length > 0.1 && length <= 1) {
                return v.scale(1 / length);
            }
        }
    }

    /** A random direction on the side of unit n. */
    private static Vector3d hemisphere(Vector3d n, Random random) {
        Vector3d v = direction(random);
        return v.dot(n) >= 0 ? v : v.scale(-1);
    }
}
