package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Shading;
import glint.math.Vector3d;
import glint.scene.Camera;
import glint.scene.Material;
import glint.scene.MaterialType;
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

    @Test
    void fewSpheresGetNoHierarchy() {
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, 1, 0, 1e-9);
        RenderScene small = RenderScene.compile(randomSpheres(new SplittableRandom(1), 5), settings);
        assertFalse(small.hasHierarchy());
    }
}
