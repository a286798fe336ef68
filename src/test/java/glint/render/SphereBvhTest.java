package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Shading;
import glint.math.Vector3d;
import glint.scene.Camera;
import glint.scene.Material;
import glint.scene.MaterialType;
import glint.scene.Plane;
import glint.scene.Scene;
import glint.scene.SceneObject;
import glint.scene.Sphere;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The hierarchy finds exactly what testing every sphere finds. */
class SphereBvhTest {

    private static Scene randomSpheres(SplittableRandom random, int count) {
        List<SceneObject> objects = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            Vector3d c = new Vector3d(random.nextDouble(-20, 20), random.nextDouble(-20, 20), random.nextDouble(-20, 20));
            objects.add(new SceneObject(new Sphere(c, random.nextDouble(0.05, 2)), Material.preset(MaterialType.MATTE)));
        }
        return new Scene(Camera.defaults(), Vector3d.ZERO, Vector3d.ZERO, List.of(), objects);
    }

    @Test
    void nearestAndAnyHitAgreeWithBruteForceSkippingTheSurfaceLeft() {
        SplittableRandom random = new SplittableRandom(7);
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, 1, 0, 1e-9);
        for (int count : new int[] {17, 100, 1000}) {
            RenderScene withBvh = RenderScene.compile(randomSpheres(new SplittableRandom(count), count), settings);
            assertTrue(withBvh.hasHierarchy());
            RayCaster caster = new RayCaster();
            for (int i = 0; i < 20_000; i++) {
                double ox = random.nextDouble(-30, 30), oy = random.nextDouble(-30, 30), oz = random.nextDouble(-30, 30);
                double dx = random.nextDouble(-1, 1), dy = random.nextDouble(-1, 1), dz = random.nextDouble(-1, 1);
                if (i % 7 == 0) {
                    dx = 0; // axis-parallel rays exercise the slab test's zero components
                }
                if (i % 11 == 0) {
                    dy = 0;
                    dz = 0;
                    dx = 1;
                }
                double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
                dx /= len;
                dy /= len;
                dz /= len;
                int skipped = random.nextInt(count + 1) - 1; // -1: none
                double brute = Intersect.MISS;
                for (int s = 0; s < count; s++) {
                    if (s == skipped) {
                        continue;
                    }
                    int k = 4 * s;
                    brute = Math.min(brute, Intersect.sphere(withBvh.spheres[k], withBvh.spheres[k + 1],
                            withBvh.spheres[k + 2], withBvh.spheres[k + 3], ox, oy, oz, dx, dy, dz));
                }
                boolean found = caster.nearest(withBvh, ox, oy, oz, dx, dy, dz, RayCaster.surfaceId(skipped, -1));
                assertEquals(brute < Intersect.MISS, found);
                assertEquals(brute, caster.hitT, 0);
                double limit = random.nextDouble(0, 60);
                assertEquals(brute < limit, caster.occluded(withBvh, ox, oy, oz, dx, dy, dz, limit,
                        RayCaster.surfaceId(skipped, -1)));
            }
        }
    }

    /** Spheres and planes: the nearest hit names the surface brute force finds, whichever kind it is. */
    @Test
    void nearestNamesTheSurfaceItMeetsAmongSpheresAndPlanes() {
        SplittableRandom random = new SplittableRandom(11);
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, 1, 0, 1e-9);
        List<SceneObject> objects = new ArrayList<>(randomSpheres(new SplittableRandom(3), 200).objects());
        Material matte = Material.preset(MaterialType.MATTE);
        objects.add(new SceneObject(new Plane(new Vector3d(0, -5, 0), new Vector3d(0, 1, 0)), matte));
        objects.add(new SceneObject(new Plane(new Vector3d(3, 0, 0), new Vector3d(-0.6, 0, 0.8)), matte));
        RenderScene scene = RenderScene.compile(new Scene(Camera.defaults(), Vector3d.ZERO, Vector3d.ZERO, List.of(),
                objects), settings);
        assertTrue(scene.hasHierarchy());
        RayCaster caster = new RayCaster();
        int planeHits = 0, sphereHits = 0;
        for (int i = 0; i < 20_000; i++) {
            double[] o = {random.nextDouble(-30, 30), random.nextDouble(-30, 30), random.nextDouble(-30, 30)};
            double[] d = unit(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
            int skippedSphere = random.nextInt(scene.sphereCount + 1) - 1;
            int skippedPlane = skippedSphere < 0 ? random.nextInt(3) - 1 : -1;
            EverySurface.Hit expected = EverySurface.nearest(scene, o[0], o[1], o[2], d[0], d[1], d[2],
                    skippedSphere, skippedPlane);
            double nearest = expected.t();
            int nearestSphere = expected.sphere(), nearestPlane = expected.plane();
            int skipCode = skippedSphere >= 0 || skippedPlane >= 0 ? RayCaster.surfaceId(skippedSphere, skippedPlane) : 0;
            assertEquals(nearest < Intersect.MISS, caster.nearest(scene, o[0], o[1], o[2], d[0], d[1], d[2], skipCode));
            assertEquals(nearest, caster.hitT, 0);
            assertEquals(nearestSphere, caster.hitSphere, "sphere met by ray " + i);
            assertEquals(nearestPlane, caster.hitPlane, "plane met by ray " + i);
            double limit = random.nextDouble(0, 60);
            assertEquals(nearest < limit, caster.occluded(scene, o[0], o[1], o[2], d[0], d[1], d[2], limit, skipCode));
            planeHits += nearestPlane >= 0 ? 1 : 0;
            sphereHits += nearestSphere >= 0 ? 1 : 0;
        }
        assertTrue(planeHits > 1000 && sphereHits > 1000, planeHits + " plane hits, " + sphereHits + " sphere hits");
    }

    /**
     * Spheres spaced ever wider apart (x = 4^i) make each binned split peel off the farthest few: a
     * hierarchy over a hundred levels deep (a balanced one would have 6), which the traversal must
     * still search whole.
     */
    @Test
    void aLopsidedHierarchyIsSearchedWhole() {
        List<SceneObject> objects = new ArrayList<>();
        for (int i = 0; i < 250; i++) {
            objects.add(new SceneObject(new Sphere(new Vector3d(Math.pow(4, i), 0, 0), 0.4),
                    Material.preset(MaterialType.MATTE)));
        }
        RenderScene scene = RenderScene.compile(new Scene(Camera.defaults(), Vector3d.ZERO, Vector3d.ZERO, List.of(),
                objects), new RenderSettings(Shading.COOK_TORRANCE, 1, 0, 1e-9));
        assertTrue(scene.bvh.depth > 100, "depth " + scene.bvh.depth);
        RayCaster caster = new RayCaster();
        // along the row from its near end: the sphere at x = 1 is met first, at the bottom of the hierarchy
        assertTrue(caster.nearest(scene, -5, 0, 0, 1, 0, 0, 0));
        assertEquals(5.6, caster.hitT, 1e-12);
        assertTrue(caster.occluded(scene, -5, 0, 0, 1, 0, 0, 10, 0));
        // inside every box, 0.55 from the axis: no sphere, after every leaf is searched
        double[] d = unit(1, 0, 0);
        assertFalse(caster.nearest(scene, -5, 0.39, 0.39, d[0], d[1], d[2], 0));
        assertFalse(caster.occluded(scene, -5, 0.39, 0.39, d[0], d[1], d[2], Intersect.MISS, 0));
    }

    private static double[] unit(double x, double y, double z) {
        double length = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / length, y / length, z / length};
    }

    @Test
    void fewSpheresGetNoHierarchy() {
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, 1, 0, 1e-9);
        RenderScene small = RenderScene.compile(randomSpheres(new SplittableRandom(1), 5), settings);
        assertFalse(small.hasHierarchy());
    }
}
