package glint.accel;

import glint.geometry.Primitives;
import glint.geometry.PlaneKind;
import glint.geometry.PrimitiveKind;
import glint.geometry.SphereKind;
import glint.geometry.Hit;
import glint.geometry.DiscKind;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * Which interiors are empty: the same answer as asking every overlapping pair
 * ({@link PairSweepReference}), with work that grows with the number of primitives however they
 * are arranged. Work is counted, not timed: the pairs the compiler looks at (it counts them), and
 * the tests it asks of a kind ({@code reachesInto}, counted by a kind wrapped around the spheres).
 */
class EmptyInteriorsTest {

    private static final long SEED = 0x5eed_e1L;

    @Test
    void theSameInteriorsAreEmptyAsWhenEveryOverlappingPairIsAsked() {
        SplittableRandom random = new SplittableRandom(SEED);
        int emptyFound = 0, reachedFound = 0;
        for (int scene = 0; scene < 400; scene++) {
            Primitives primitives = randomScene(random);
            boolean[] expected = PairSweepReference.findEmpty(primitives);
            assertArrayEquals(expected, EmptyInteriors.findEmpty(primitives), "scene " + scene);
            assertArrayEquals(expected, EmptyInteriors.findEmpty(primitives, new long[1], 0), "scene " + scene + ", groups");
            for (int q = 0; q < expected.length; q++) {
                if (primitives.closed(q)) {
                    if (expected[q]) {
                        emptyFound++;
                    } else {
                        reachedFound++;
                    }
                }
            }
        }
        assertTrue(emptyFound > 1000 && reachedFound > 1000, emptyFound + " empty, " + reachedFound + " reached");
    }

    /**
     * The planes asked of groups of spheres (as above 65,536 plane-sphere pairs) give the same
     * answer, here for every scene: many planes, some of them touching a sphere to rounding.
     */
    @Test
    void planesAskedOfGroupsGiveTheSameInteriors() {
        SplittableRandom random = new SplittableRandom(SEED + 2);
        int emptyFound = 0, reachedFound = 0;
        for (int scene = 0; scene < 300; scene++) {
            Primitives primitives = manyPlanes(random);
            boolean[] expected = PairSweepReference.findEmpty(primitives);
            assertArrayEquals(expected, EmptyInteriors.findEmpty(primitives, new long[1], 0), "scene " + scene);
            for (int q = 0; q < primitives.kind(0).count(); q++) {
                if (expected[q]) {
                    emptyFound++;
                } else {
                    reachedFound++;
                }
            }
        }
        assertTrue(emptyFound > 1000 && reachedFound > 1000, emptyFound + " empty, " + reachedFound + " reached");
    }

    /**
     * 50,000 planes and 50,000 separate spheres (the default max_objects): each plane is asked of
     * groups, not of every sphere (that would be 2.5 billion pairs).
     */
    @Test
    void fiftyThousandPlanesAndFiftyThousandSeparateSpheresTakeFarLessThanTheirProduct() {
        int n = 50_000;
        double[] s = new double[4 * n];
        double[] planes = new double[4 * n];
        for (int i = 0; i < n; i++) {
            s[4 * i] = i; // in a row, so that the spheres' own sweep is linear too
            s[4 * i + 3] = 0.3;
            planes[4 * i + 1] = 1; // floors below them all
            planes[4 * i + 3] = -1000 - i;
        }
        long[] pairs = new long[1];
        boolean[] empty = EmptyInteriors.findEmpty(new Primitives(List.of(new SphereKind(s), new PlaneKind(planes))), pairs);
        for (int q = 0; q < n; q++) {
            assertTrue(empty[q], "sphere " + q);
        }
        assertTrue(pairs[0] <= 10L * n, pairs[0] + " pairs looked at"); // 238,016 here
    }

    /** Up to 300 spheres (some coincident or touching) and up to 60 planes, some tangent to a sphere. */
    private static Primitives manyPlanes(SplittableRandom random) {
        int count = 1 + random.nextInt(300);
        double[] s = new double[4 * count];
        for (int i = 0; i < count; i++) {
            int k = 4 * i;
            if (i > 0 && random.nextInt(6) == 0) {
                System.arraycopy(s, 4 * random.nextInt(i), s, k, 4);
            } else {
                double scale = random.nextInt(10) == 0 ? 1e6 : 1;
                s[k] = random.nextDouble(-30, 30) * scale;
                s[k + 1] = random.nextDouble(-30, 30) * scale;
                s[k + 2] = random.nextDouble(-30, 30) * scale;
                s[k + 3] = random.nextDouble(0.01, 2) * (random.nextInt(30) == 0 ? 20 : 1);
            }
        }
        int planes = random.nextInt(60);
        double[] p = new double[4 * planes];
        for (int i = 0; i < planes; i++) {
            double x = random.nextDouble(-1, 1), y = random.nextDouble(-1, 1), z = random.nextDouble(-1, 1);
            if (random.nextBoolean()) { // axis-aligned, as floors and walls are
                x = 0;
                z = 0;
                y = 1;
            }
            double length = Math.max(1e-9, Math.sqrt(x * x + y * y + z * z));
            double nx = x / length, ny = y / length, nz = z / length;
            p[4 * i] = nx;
            p[4 * i + 1] = ny;
            p[4 * i + 2] = nz;
            int o = 4 * random.nextInt(count);
            double centre = nx * s[o] + ny * s[o + 1] + nz * s[o + 2];
            p[4 * i + 3] = switch (random.nextInt(3)) {
                case 0 -> centre + s[o + 3]; // tangent to a sphere, to rounding
                case 1 -> centre + s[o + 3] * random.nextDouble(1, 1 + 1e-9); // just clear of it
                default -> random.nextDouble(-40, 40);
            };
        }
        return new Primitives(List.of(new SphereKind(s), new PlaneKind(p)));
    }

    @Test
    void aHundredThousandCoincidentSpheresTakeLinearWork() {
        int n = 100_000;
        double[] s = new double[4 * n];
        for (int i = 0; i < n; i++) {
            s[4 * i + 1] = 1;
            s[4 * i + 3] = 1;
        }
        assertLinear(s, n);
    }

    @Test
    void aHundredThousandNestedSpheresTakeLinearWork() {
        int n = 100_000;
        double[] s = new double[4 * n];
        for (int i = 0; i < n; i++) {
            s[4 * i + 3] = 1 + i * 1e-3; // one centre, every radius different
        }
        assertLinear(s, n);
    }

    @Test
    void aHundredThousandSpheresThatAllOverlapTakeLinearWork() {
        int n = 100_000;
        SplittableRandom random = new SplittableRandom(SEED + 1);
        double[] s = new double[4 * n];
        for (int i = 0; i < n; i++) {
            s[4 * i] = random.nextDouble(-1, 1);
            s[4 * i + 1] = random.nextDouble(-1, 1);
            s[4 * i + 2] = random.nextDouble(-1, 1);
            s[4 * i + 3] = random.nextDouble(2, 3);
        }
        assertLinear(s, n);
    }

    /**
     * None of the spheres is empty, found looking at no more than 3 pairs a sphere and asking at most
     * 4 tests a sphere (every pair of them is 5 billion).
     */
    private static void assertLinear(double[] spheres, int n) {
        Counting counted = new Counting(new SphereKind(spheres));
        long[] pairs = new long[1];
        boolean[] empty = EmptyInteriors.findEmpty(new Primitives(List.of(counted, new PlaneKind(new double[] {0, 1, 0, -5}))),
                pairs);
        for (int q = 0; q < n; q++) {
            assertEquals(false, empty[q], "sphere " + q);
        }
        assertTrue(pairs[0] <= 3L * n, pairs[0] + " pairs looked at for " + n + " spheres");
        assertTrue(counted.tests <= 4L * n, counted.tests + " tests for " + n + " spheres");
    }

    /** SphereKind in clusters (coincident, nested, overlapping, apart), planes and discs. */
    private static Primitives randomScene(SplittableRandom random) {
        int count = 1 + random.nextInt(120);
        double[] s = new double[4 * count];
        for (int i = 0; i < count; i++) {
            int k = 4 * i;
            int shape = random.nextInt(5);
            if (i > 0 && shape == 0) { // coincident with an earlier one
                System.arraycopy(s, 4 * random.nextInt(i), s, k, 4);
            } else if (i > 0 && shape == 1) { // nested in an earlier one, or around it
                System.arraycopy(s, 4 * random.nextInt(i), s, k, 4);
                s[k + 3] *= random.nextDouble(0.2, 2);
            } else if (i > 0 && shape == 2) { // touching an earlier one, to rounding
                int o = 4 * random.nextInt(i);
                double r = random.nextDouble(0.05, 2);
                s[k] = s[o] + s[o + 3] + r;
                s[k + 1] = s[o + 1];
                s[k + 2] = s[o + 2];
                s[k + 3] = r;
            } else {
                double spread = shape == 3 ? 3 : 30;
                s[k] = random.nextDouble(-spread, spread);
                s[k + 1] = random.nextDouble(-spread, spread);
                s[k + 2] = random.nextDouble(-spread, spread);
                s[k + 3] = random.nextInt(40) == 0 ? random.nextDouble(5, 40) : random.nextDouble(0.05, 3);
            }
        }
        List<PrimitiveKind> kinds = new ArrayList<>(List.of(new SphereKind(s)));
        int planes = random.nextInt(4);
        double[] p = new double[4 * planes];
        for (int i = 0; i < planes; i++) {
            double x = random.nextDouble(-1, 1), y = random.nextDouble(-1, 1), z = random.nextDouble(-1, 1);
            double length = Math.max(1e-9, Math.sqrt(x * x + y * y + z * z));
            p[4 * i] = x / length;
            p[4 * i + 1] = y / length;
            p[4 * i + 2] = z / length;
            p[4 * i + 3] = random.nextDouble(-30, 30);
        }
        kinds.add(new PlaneKind(p));
        int discs = random.nextInt(4);
        double[] d = new double[7 * discs];
        for (int i = 0; i < discs; i++) {
            d[7 * i] = random.nextDouble(-10, 10);
            d[7 * i + 1] = random.nextDouble(-10, 10);
            d[7 * i + 2] = random.nextDouble(-10, 10);
            d[7 * i + 4] = 1;
            d[7 * i + 6] = random.nextDouble(0.5, 5);
        }
        kinds.add(new DiscKind(d));
        return new Primitives(kinds);
    }

    /** A kind that counts the tests asked of it and passes everything else on. */
    private static final class Counting implements PrimitiveKind {
        private final PrimitiveKind shape;
        long tests;

        Counting(PrimitiveKind shape) {
            this.shape = shape;
        }

        @Override
        public boolean reachesInto(int i, double cx, double cy, double cz, double r) {
            tests++;
            return shape.reachesInto(i, cx, cy, cz, r);
        }

        @Override
        public int count() {
            return shape.count();
        }

        @Override
        public boolean bounded(int i) {
            return shape.bounded(i);
        }

        @Override
        public void bounds(int i, double[] box, int at) {
            shape.bounds(i, box, at);
        }

        @Override
        public double intersect(int i, double ox, double oy, double oz, double dx, double dy, double dz, double tMax) {
            return shape.intersect(i, ox, oy, oz, dx, dy, dz, tMax);
        }

        @Override
        public void surfaceAt(int i, double px, double py, double pz, Hit hit) {
            shape.surfaceAt(i, px, py, pz, hit);
        }

        @Override
        public void boundingBall(int i, double[] ball) {
            shape.boundingBall(i, ball);
        }

        @Override
        public boolean closed() {
            return shape.closed();
        }
    }
}
