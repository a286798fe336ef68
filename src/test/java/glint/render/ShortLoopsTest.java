package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Shading;
import glint.math.Vector3d;
import glint.scene.Camera;
import glint.scene.Light;
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

/**
 * The ray caster's loops over a small scene's planes and spheres run in loops the JIT knows are
 * short ({@link RayCaster#few}): the bounds they are given hold for every scene, and scenes on
 * either side of each bound find what testing every surface finds.
 */
class ShortLoopsTest {

    private static final RenderSettings SETTINGS = new RenderSettings(Shading.COOK_TORRANCE, 1, 0, 1e-9);
    private static final Material MATTE = Material.preset(MaterialType.MATTE);

    private static RenderScene randomScene(SplittableRandom random, int spheres, int planes) {
        List<SceneObject> objects = new ArrayList<>();
        for (int i = 0; i < spheres; i++) {
            Vector3d c = new Vector3d(random.nextDouble(-8, 8), random.nextDouble(-8, 8), random.nextDouble(-8, 8));
            objects.add(new SceneObject(new Sphere(c, random.nextDouble(0.3, 3)), MATTE));
        }
        for (int i = 0; i < planes; i++) {
            double[] n = RandomScenes.unitVector(random);
            Vector3d point = new Vector3d(random.nextDouble(-15, 15), random.nextDouble(-15, 15), random.nextDouble(-15, 15));
            objects.add(new SceneObject(new Plane(point, new Vector3d(n[0], n[1], n[2])), MATTE));
        }
        return RenderScene.compile(new Scene(Camera.defaults(), Vector3d.ZERO, Vector3d.ZERO, List.of(), objects),
                SETTINGS);
    }

    @Test
    void aSceneWithoutAHierarchyHasAtMostItsBoundOfSpheres() {
        SplittableRandom random = new SplittableRandom(41);
        for (int count = 1; count <= RenderScene.BVH_MIN_SPHERES + 4; count++) {
            RenderScene scene = randomScene(random, count, 0);
            assertEquals(count > RenderScene.BVH_MIN_SPHERES, scene.hasHierarchy(), count + " spheres");
        }
    }

    @Test
    void everyLeafOfAHierarchyHoldsAtMostItsBoundOfSpheres() {
        SplittableRandom random = new SplittableRandom(43);
        for (int count : new int[] {RenderScene.BVH_MIN_SPHERES + 1, 40, 333}) {
            SphereBvh bvh = randomScene(random, count, 0).bvh;
            int spheresInLeaves = 0;
            for (int node = 0; node < bvh.nodeCount; node++) {
                int spheres = bvh.links[2 * node + 1];
                assertTrue(spheres <= SphereBvh.LEAF_SIZE, "node " + node + " holds " + spheres);
                spheresInLeaves += Math.max(spheres, 0);
            }
            assertEquals(count, spheresInLeaves);
        }
    }

    @Test
    void pointLightsHaveConesOnlyForTheirBoundOfSpheres() {
        for (int count = 1; count <= LightCones.MOST_SPHERES + 2; count++) {
            List<SceneObject> objects = new ArrayList<>();
            for (int i = 0; i < count; i++) {
                objects.add(new SceneObject(new Sphere(new Vector3d(4 * i, 0, 0), 1), MATTE));
            }
            Scene scene = new Scene(Camera.defaults(), Vector3d.ZERO, Vector3d.ZERO,
                    List.of(new Light.Point(new Vector3d(0, 30, 0), new Vector3d(1, 1, 1), 100)), objects);
            LightCones cones = RenderScene.compile(scene, SETTINGS).lightCones[0];
            assertEquals(count <= LightCones.MOST_SPHERES, cones != null, count + " spheres");
            if (cones != null) {
                assertEquals(count, cones.count);
            }
        }
    }

    /**
     * Scenes of 0, 1, {@link RayCaster#FEW_PLANES} and more planes, with spheres up to and past the
     * bound without a hierarchy: the nearest hit and any hit agree with testing every surface, the
     * planes past the first few included.
     */
    @Test
    void scenesOnEitherSideOfTheBoundsFindWhatEverySurfaceFinds() {
        SplittableRandom random = new SplittableRandom(53);
        RayCaster caster = new RayCaster();
        int hitsOnLaterPlanes = 0;
        for (int spheres : new int[] {0, 1, RenderScene.BVH_MIN_SPHERES, RenderScene.BVH_MIN_SPHERES + 1}) {
            for (int planes : new int[] {0, 1, RayCaster.FEW_PLANES, RayCaster.FEW_PLANES + 3}) {
                RenderScene scene = randomScene(random, spheres, planes);
                for (int i = 0; i < 3000; i++) {
                    double[] o = {random.nextDouble(-20, 20), random.nextDouble(-20, 20), random.nextDouble(-20, 20)};
                    double[] d = RandomScenes.unitVector(random);
                    int skippedSphere = random.nextInt(spheres + 1) - 1;
                    int skippedPlane = skippedSphere < 0 ? random.nextInt(planes + 1) - 1 : -1;
                    int skipCode = skippedSphere >= 0 || skippedPlane >= 0
                            ? RayCaster.surfaceId(skippedSphere, skippedPlane) : 0;
                    EverySurface.Hit expected = EverySurface.nearest(scene, o[0], o[1], o[2], d[0], d[1], d[2],
                            skippedSphere, skippedPlane);
                    String ray = spheres + " spheres, " + planes + " planes, ray " + i;
                    assertEquals(expected.t() < Intersect.MISS,
                            caster.nearest(scene, o[0], o[1], o[2], d[0], d[1], d[2], skipCode), ray);
                    assertEquals(expected.t(), caster.hitT, 0, ray);
                    assertEquals(expected.sphere(), caster.hitSphere, ray);
                    assertEquals(expected.plane(), caster.hitPlane, ray);
                    double limit = random.nextDouble(0, 40);
                    assertEquals(expected.t() < limit,
                            caster.occluded(scene, o[0], o[1], o[2], d[0], d[1], d[2], limit, skipCode), ray);
                    hitsOnLaterPlanes += expected.plane() >= RayCaster.FEW_PLANES ? 1 : 0;
                }
            }
        }
        assertTrue(hitsOnLaterPlanes > 100, hitsOnLaterPlanes + " nearest hits on planes past the first few");
    }
}
