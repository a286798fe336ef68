package glint.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
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

/** Which spheres nothing reaches into, and that a ray inside one finds what a full search finds. */
class EmptySpheresTest {

    private static final RenderSettings SETTINGS = new RenderSettings(Shading.COOK_TORRANCE, 5, 0, 1e-9);

    private static RenderScene compile(String objects) {
        return RenderScene.compile(Renders.scene("objects:\n" + objects), SETTINGS);
    }

    @Test
    void aTangentFloorAndATouchingSphereLeaveASphereEmpty() {
        RenderScene s = compile("""
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
                  - {type: sphere, center: [0, 1, 0], radius: 1}
                  - {type: sphere, center: [2, 1, 0], radius: 1}
                """);
        assertArrayEquals(new boolean[] {true, true}, s.sphereIsEmpty);
    }

    @Test
    void aCuttingPlaneAnOverlapAndANestedSphereAreFound() {
        RenderScene s = compile("""
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
                  - {type: sphere, center: [0, 0.5, 0], radius: 1}
                  - {type: sphere, center: [10, 5, 0], radius: 1}
                  - {type: sphere, center: [11.5, 5, 0], radius: 1}
                  - {type: sphere, center: [20, 5, 0], radius: 2}
                  - {type: sphere, center: [20.5, 5, 0], radius: 0.5}
                  - {type: sphere, center: [-10, 5, 0], radius: 1}
                """);
        assertArrayEquals(new boolean[] {false, false, false, false, false, true}, s.sphereIsEmpty,
                "cut by the floor; overlapping pair; nested pair; alone");
    }

    @Test
    void theHierarchyFindsWhatComparingEveryPairFinds() {
        for (int seed = 1; seed <= 5; seed++) {
            RenderScene s = RenderScene.compile(randomScene(new SplittableRandom(seed), 300), SETTINGS);
            assertTrue(s.hasHierarchy());
            for (int i = 0; i < s.sphereCount; i++) {
                assertEquals(emptyByEveryPair(s, i), s.sphereIsEmpty[i], "sphere " + i + " of seed " + seed);
            }
        }
    }

    @Test
    void aRayInsideASphereFindsWhatTheFullSearchFinds() {
        SplittableRandom random = new SplittableRandom(11);
        int emptyTested = 0, spheresTested = 0;
        for (int count : new int[] {4, 300}) {
            RenderScene s = RenderScene.compile(randomScene(new SplittableRandom(count), count), SETTINGS);
            RayCaster inside = new RayCaster();
            RayCaster full = new RayCaster();
            for (int i = 0; i < s.sphereCount; i++) {
                int k = 4 * i;
                for (int ray = 0; ray < 200; ray++) {
                    double[] d = unitVector(random);
                    double[] u = unitVector(random);
                    double along = random.nextDouble(0, 0.999) * s.spheres[k + 3];
                    double ox = s.spheres[k] + along * u[0];
                    double oy = s.spheres[k + 1] + along * u[1];
                    double oz = s.spheres[k + 2] + along * u[2];
                    boolean foundInside = inside.nearest(s, ox, oy, oz, d[0], d[1], d[2], RayCaster.insideOf(i));
                    boolean foundFull = full.nearest(s, ox, oy, oz, d[0], d[1], d[2], RayCaster.surfaceId(-1, -1));
                    assertEquals(foundFull, foundInside);
                    assertEquals(full.hitT, inside.hitT, 0);
                    assertEquals(full.hitSphere, inside.hitSphere);
                    assertEquals(full.hitPlane, inside.hitPlane);
                }
                emptyTested += s.sphereIsEmpty[i] ? 1 : 0;
                spheresTested++;
            }
        }
        assertTrue(emptyTested > 0 && emptyTested < spheresTested, "both kinds of sphere were tried");
    }

    private static boolean emptyByEveryPair(RenderScene s, int i) {
        double[] c = s.spheres;
        for (int j = 0; j < s.sphereCount; j++) {
            double distance = Math.sqrt(Math.pow(c[4 * i] - c[4 * j], 2) + Math.pow(c[4 * i + 1] - c[4 * j + 1], 2)
                    + Math.pow(c[4 * i + 2] - c[4 * j + 2], 2));
            if (j != i && distance < c[4 * i + 3] + c[4 * j + 3]) {
                return false;
            }
        }
        // the floor y = 0
        return !(Math.abs(c[4 * i + 1]) < c[4 * i + 3]);
    }

    /** Spheres of random size above, on and through a floor, packed closely enough that some overlap. */
    private static Scene randomScene(SplittableRandom random, int count) {
        List<SceneObject> objects = new ArrayList<>();
        Material matte = Material.preset(MaterialType.MATTE);
        objects.add(new SceneObject(new Plane(Vector3d.ZERO, new Vector3d(0, 1, 0)), matte));
        double extent = Math.cbrt(count) * 2.5;
        for (int i = 0; i < count; i++) {
            Vector3d c = new Vector3d(random.nextDouble(-extent, extent), random.nextDouble(-1, 2 * extent),
                    random.nextDouble(-extent, extent));
            objects.add(new SceneObject(new Sphere(c, random.nextDouble(0.2, 1.2)), matte));
        }
        return new Scene(Camera.defaults(), Vector3d.ZERO, Vector3d.ZERO, List.of(), objects);
    }

    private static double[] unitVector(SplittableRandom random) {
        while (true) {
            double x = random.nextDouble(-1, 1), y = random.nextDouble(-1, 1), z = random.nextDouble(-1, 1);
            double length = Math.sqrt(x * x + y * y + z * z);
            if (length > 0.1 && length <= 1) {
                return new double[] {x / length, y / length, z / length};
            }
        }
    }
}
