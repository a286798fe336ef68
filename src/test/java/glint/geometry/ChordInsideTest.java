package glint.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** A sphere's chords in closed form end where the intersection finds them, at the angle they start at. */
class ChordInsideTest {

    @Test
    void aChordEndsWhereTheRayFromInsideMeetsTheSphere() {
        SplittableRandom random = new SplittableRandom(20_261_202L);
        for (int trial = 0; trial < 10_000; trial++) {
            double radius = Math.exp(random.nextDouble(-4, 4));
            double[] centre = {random.nextDouble(-50, 50), random.nextDouble(-50, 50), random.nextDouble(-50, 50)};
            SphereKind sphere = new SphereKind(new double[] {centre[0], centre[1], centre[2], radius});
            double[] n = unit(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
            double[] u = unit(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
            double un = u[0] * n[0] + u[1] * n[1] + u[2] * n[2];
            if (un > -1e-3) { // into the sphere, not grazing
                continue;
            }
            double px = centre[0] + radius * n[0], py = centre[1] + radius * n[1], pz = centre[2] + radius * n[2];
            Hit end = new Hit();
            double cos = sphere.chordInside(0, px, py, pz, u[0], u[1], u[2], -un, 0, end);
            assertEquals(-un, cos, 0, "a sphere's chord meets it again at the angle it starts at");
            double step = 1e-6 * radius; // from just inside, the intersection finds the far side
            double t = step + sphere.intersect(0, px + step * u[0], py + step * u[1], pz + step * u[2], u[0], u[1],
                    u[2], Intersect.MISS);
            double scale = radius + Math.abs(centre[0]) + Math.abs(centre[1]) + Math.abs(centre[2]);
            assertEquals(t, end.t, 1e-12 * scale, "chord length, trial " + trial);
            assertEquals(px + t * u[0], end.px, 1e-12 * scale);
            assertEquals(py + t * u[1], end.py, 1e-12 * scale);
            assertEquals(pz + t * u[2], end.pz, 1e-12 * scale);
            double nLength = Math.sqrt(end.nx * end.nx + end.ny * end.ny + end.nz * end.nz);
            assertEquals(1, nLength, 1e-12 * scale / radius, "outward normal of unit length");
            assertEquals(cos, u[0] * end.nx + u[1] * end.ny + u[2] * end.nz, 1e-12 * scale / radius,
                    "the ray leaves along the outward normal at the same cosine");
        }
    }

    @Test
    void aSphereNoLargerThanTheOffsetHasNoClosedForm() {
        SphereKind sphere = new SphereKind(new double[] {0, 0, 0, 1e-3});
        Hit end = new Hit();
        assertTrue(Double.isNaN(sphere.chordInside(0, 0, 1e-3, 0, 0, -1, 0, 1, 1e-3, end)));
        assertEquals(1, sphere.chordInside(0, 0, 1e-3, 0, 0, -1, 0, 1, 0.9e-3, end), 0);
        assertEquals(2e-3, end.t, 0, "straight through the centre, a diameter");
    }

    @Test
    void aKindWithoutAClosedFormSaysSo() {
        PlaneKind planes = new PlaneKind(new double[] {0, 1, 0, 0});
        assertTrue(Double.isNaN(planes.chordInside(0, 0, 0, 0, 0, -1, 0, 1, 0, new Hit())));
    }

    private static double[] unit(double x, double y, double z) {
        double length = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / length, y / length, z / length};
    }
}
