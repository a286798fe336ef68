package glint.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Shading;
import glint.input.InputException;
import glint.math.Vector3d;
import glint.scene.Camera;
import glint.scene.Light;
import glint.scene.Material;
import glint.scene.MaterialType;
import glint.scene.Plane;
import glint.scene.Scene;
import glint.scene.SceneLimits;
import glint.scene.SceneLoader;
import glint.scene.SceneObject;
import glint.scene.Sphere;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A ray leaving a sphere on its outer side tests only the spheres its direction's cell lists,
 * nearest first, and stops at the first it cannot meet before the hit found so far: it must find
 * the hit a test of every sphere and plane finds.
 */
class NeighbourCellsTest {

    private static final Material GLASS = Material.preset(MaterialType.GLASS);
    private static final Material MATTE = Material.preset(MaterialType.MATTE);

    private static RenderScene scene(List<SceneObject> objects, double epsilon, Shading shading) {
        return RenderScene.compile(new Scene(Camera.defaults(), Vector3d.ZERO, Vector3d.ZERO,
                List.of(new Light.Point(new Vector3d(0, 50, 0), new Vector3d(1, 1, 1), 1)), objects),
                new RenderSettings(shading, 5, 0, epsilon));
    }

    /** Spheres anywhere in a box (overlapping, nested and touching ones among them) above a floor. */
    private static List<SceneObject> randomSpheres(SplittableRandom random, int count) {
        List<SceneObject> objects = new ArrayList<>();
        double extent = Math.cbrt(count) * 2;
        for (int i = 0; i < count; i++) {
            Vector3d centre = new Vector3d(random.nextDouble(-extent, extent), random.nextDouble(-extent, extent),
                    random.nextDouble(-extent, extent));
            objects.add(new SceneObject(new Sphere(centre, random.nextDouble(0.05, 1.5)), GLASS));
        }
        objects.add(new SceneObject(new Plane(new Vector3d(0, -extent, 0), new Vector3d(0, 1, 0)), MATTE));
        return objects;
    }

    /** The nearest hit along the ray over every sphere but {@code skipped} and every plane: {t, sphere, plane}. */
    private static double[] nearestOfAll(RenderScene s, double[] o, double[] d, int skipped) {
        double[] best = {Intersect.MISS, -1, -1};
        for (int p = 0; p < s.planeCount; p++) {
            int k = 4 * p;
            double t = Intersect.plane(s.planes[k], s.planes[k + 1], s.planes[k + 2], s.planes[k + 3],
                    o[0], o[1], o[2], d[0], d[1], d[2]);
            if (t < best[0]) {
                best = new double[] {t, -1, p};
            }
        }
        for (int j = 0; j < s.sphereCount; j++) {
            int k = 4 * j;
            double t = j == skipped ? Intersect.MISS : Intersect.sphere(s.spheres[k], s.spheres[k + 1],
                    s.spheres[k + 2], s.spheres[k + 3], o[0], o[1], o[2], d[0], d[1], d[2]);
            if (t < best[0]) {
                best = new double[] {t, j, -1};
            }
        }
        return best;
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    /**
     * A unit direction from o grazing sphere j: at the cone of its silhouette, turned in or out by a
     * relative {@code turn} of the cone's half-angle.
     */
    private static double[] grazing(RenderScene s, int j, double[] o, double turn, SplittableRandom random) {
        int k = 4 * j;
        double[] w = {s.spheres[k] - o[0], s.spheres[k + 1] - o[1], s.spheres[k + 2] - o[2]};
        double distance = Math.sqrt(dot(w, w));
        if (!(distance > s.spheres[k + 3] * 1.01)) {
            return null; // o inside or on the sphere: no silhouette
        }
        for (int a = 0; a < 3; a++) {
            w[a] /= distance;
        }
        double[] u = RandomScenes.unitVector(random);
        double along = dot(u, w);
        for (int a = 0; a < 3; a++) {
            u[a] -= along * w[a];
        }
        double length = Math.sqrt(dot(u, u));
        double angle = Math.asin(s.spheres[k + 3] / distance) * (1 + turn);
        double[] d = new double[3];
        for (int a = 0; a < 3; a++) {
            d[a] = Math.cos(angle) * w[a] + Math.sin(angle) * u[a] / length;
        }
        double norm = Math.sqrt(dot(d, d));
        return new double[] {d[0] / norm, d[1] / norm, d[2] / norm};
    }

    @ParameterizedTest
    @ValueSource(doubles = {1e-9, 1e-6, 1e-3, 0.05})
    void leavingRaysFindTheNearestHitOfAll(double epsilon) {
        SplittableRandom random = new SplittableRandom(Double.hashCode(epsilon));
        int checked = 0, hitSpheres = 0, grazed = 0, listed = 0;
        for (int count : new int[] {8, 12, 40, RenderScene.NEIGHBOUR_MAX_SPHERES}) {
            for (int trial = 0; trial < 3; trial++) {
                RenderScene s = scene(randomSpheres(random, count), epsilon, Shading.COOK_TORRANCE);
                RayCaster caster = new RayCaster();
                for (int i = 0; i < s.sphereCount; i++) {
                    if (s.neighbours[i] == null) {
                        continue; // beyond the budget: the rays search the hierarchy
                    }
                    listed++;
                    int k = 4 * i;
                    for (int ray = 0; ray < 120; ray++) {
                        // a point on sphere i, moved out by up to the offset of a ray leaving it
                        double[] n = RandomScenes.unitVector(random);
                        double[] p = {s.spheres[k] + s.spheres[k + 3] * n[0], s.spheres[k + 1] + s.spheres[k + 3] * n[1],
                                s.spheres[k + 2] + s.spheres[k + 3] * n[2]};
                        double offset = epsilon * Math.max(1, Math.sqrt(dot(p, p))) * random.nextDouble();
                        double[] o = {p[0] + offset * n[0], p[1] + offset * n[1], p[2] + offset * n[2]};
                        double[] d = ray % 2 == 0 ? RandomScenes.unitVector(random)
                                : grazing(s, random.nextInt(s.sphereCount), o, random.nextDouble(-1e-6, 1e-6), random);
                        if (d == null || dot(d, n) <= 0) {
                            continue; // rays leave a sphere's outer side outwards
                        }
                        grazed += ray % 2;
                        double[] expected = nearestOfAll(s, o, d, i);
                        boolean found = caster.nearest(s, o[0], o[1], o[2], d[0], d[1], d[2], RayCaster.surfaceId(i, -1));
                        String where = String.format("%d spheres, leaving sphere %d at (%g, %g, %g) along (%g, %g, %g)",
                                count, i, o[0], o[1], o[2], d[0], d[1], d[2]);
                        assertEquals(expected[0] < Intersect.MISS, found, where);
                        assertEquals(expected[0], caster.hitT, where);
                        assertEquals((int) expected[1], caster.hitSphere, where);
                        assertEquals((int) expected[2], caster.hitPlane, where);
                        checked++;
                        hitSpheres += caster.hitSphere >= 0 ? 1 : 0;
                    }
                }
            }
        }
        assertTrue(listed > 250, "spheres with cells: " + listed);
        assertTrue(checked > 15000, "rays checked: " + checked);
        assertTrue(hitSpheres > checked / 10, "rays meeting a sphere: " + hitSpheres);
        assertTrue(grazed > checked / 3, "grazing rays: " + grazed);
    }

    @Test
    void everyListIsNearestFirstAndItsDistancesAreLowerBounds() {
        SplittableRandom random = new SplittableRandom(7);
        RenderScene s = scene(randomSpheres(random, 30), 1e-6, Shading.COOK_TORRANCE);
        for (int i = 0; i < s.sphereCount; i++) {
            NeighbourCells cells = s.neighbours[i];
            for (int c = 0; c + 1 < cells.cellStart.length; c++) {
                for (int e = cells.cellStart[c]; e < cells.cellStart[c + 1]; e++) {
                    assertTrue(cells.cellSpheres[e] != i, "a sphere never lists itself");
                    if (e > cells.cellStart[c]) {
                        assertTrue(cells.cellNear[e - 1] <= cells.cellNear[e], "nearest first");
                    }
                }
            }
            // the bound: centre distance less both radii and the offset, whatever the ray
            for (int e = 0; e < cells.entries(); e++) {
                int j = cells.cellSpheres[e];
                double gap = Math.sqrt(square(s.spheres[4 * i] - s.spheres[4 * j])
                        + square(s.spheres[4 * i + 1] - s.spheres[4 * j + 1])
                        + square(s.spheres[4 * i + 2] - s.spheres[4 * j + 2]))
                        - s.spheres[4 * i + 3] - s.spheres[4 * j + 3];
                assertTrue(cells.cellNear[e] < gap && cells.cellNear[e] > gap - 1e-3, "bound " + cells.cellNear[e]
                        + " for a gap of " + gap);
            }
        }
    }

    private static double square(double x) {
        return x * x;
    }

    @Test
    void onlySpheresThatRaysLeaveGetCellsAndOnlyInScenesOfEnoughSpheres() {
        List<SceneObject> objects = new ArrayList<>();
        for (int i = 0; i < RenderScene.NEIGHBOUR_MIN_SPHERES; i++) {
            objects.add(new SceneObject(new Sphere(new Vector3d(3 * i, 0, 0), 1), i % 2 == 0 ? GLASS : MATTE));
        }
        RenderScene physical = scene(objects, 1e-9, Shading.COOK_TORRANCE);
        RenderScene phong = scene(objects, 1e-9, Shading.PHONG);
        RenderScene fewer = scene(objects.subList(1, objects.size()), 1e-9, Shading.COOK_TORRANCE);
        for (int i = 0; i < objects.size(); i++) {
            boolean glass = physical.materialType[physical.sphereMaterial[i]] == RenderScene.GLASS;
            assertEquals(glass, physical.neighbours[i] != null, "matte spheres reflect nothing in cook-torrance");
            assertNotNull(phong.neighbours[i], "every phong surface reflects");
        }
        assertArrayEquals(new NeighbourCells[objects.size() - 1], fewer.neighbours);
        int many = RenderScene.NEIGHBOUR_MAX_SPHERES + 1;
        assertArrayEquals(new NeighbourCells[many],
                scene(randomSpheres(new SplittableRandom(1), many), 1e-9, Shading.PHONG).neighbours);
        // a sphere's cells hold every other sphere in some cell: here each lies in a few cells
        NeighbourCells first = phong.neighbours[0];
        assertEquals(objects.size() - 1, Arrays.stream(first.cellSpheres).distinct().count());
    }

    @Test
    void theGlassSpheresRenderAsWithoutCells() throws IOException, InputException {
        assertSameImage(SceneLoader.load(Path.of("scenes/bench/glass-25.yaml"), SceneLimits.DEFAULT), 120, 90);
        assertSameImage(SceneLoader.load(Path.of("scenes/bench/glass-10.yaml"), SceneLimits.DEFAULT), 120, 90);
    }

    @Test
    void randomScenesRenderAsWithoutCells() {
        SplittableRandom random = new SplittableRandom(31);
        for (int trial = 0; trial < 6; trial++) {
            StringBuilder yaml = new StringBuilder("""
                    camera: {position: [0, 3, -9], look_at: [0, 0.5, 0], fov: 60}
                    lights: [{type: point, position: [-4, 7, -5], color: [1, 1, 1], intensity: 80}]
                    objects:
                      - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.6, 0.6, 0.6]}}
                    """);
            String[] materials = {"{type: glass, ior: 1.5}", "{type: metal, color: [0.9, 0.8, 0.6], roughness: 0.1}",
                    "{type: matte, color: [0.7, 0.2, 0.2]}"};
            for (int i = 0; i < 12; i++) {
                double radius = random.nextDouble(0.2, 1);
                yaml.append(String.format(java.util.Locale.ROOT,
                        "  - {type: sphere, center: [%.3f, %.3f, %.3f], radius: %.3f, material: %s}%n",
                        random.nextDouble(-4, 4), random.nextDouble(0, 2.5), random.nextDouble(-2, 4), radius,
                        materials[random.nextInt(3)]));
            }
            assertSameImage(Renders.scene(yaml.toString()), 80, 60);
        }
    }

    /** Renders the scene as compiled and with no neighbour cells; the same bytes and the same rays. */
    private static void assertSameImage(Scene scene, int width, int height) {
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, 5, 1e-3, Renders.EPSILON);
        RenderScene withCells = RenderScene.compile(scene, settings);
        assertTrue(Arrays.stream(withCells.neighbours).anyMatch(c -> c != null), "the scene has cells to test");
        RenderScene withoutCells = RenderScene.compile(scene, settings);
        Arrays.fill(withoutCells.neighbours, null);
        FrameBuffer listed = new FrameBuffer(width, height), searched = new FrameBuffer(width, height);
        long raysListed = Renders.renderCountingRays(withCells, listed, 1);
        long raysSearched = Renders.renderCountingRays(withoutCells, searched, 1);
        assertArrayEquals(searched.rgb(), listed.rgb());
        assertEquals(raysSearched, raysListed, "rays cast");
    }
}
