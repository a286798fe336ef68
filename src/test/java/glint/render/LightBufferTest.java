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
 * A shadow ray that tests only the spheres its light's cones hold or its light's buffer lists for
 * its direction finds a blocker exactly when testing every sphere does; where the cones or the
 * buffer rule every sphere out, the planes alone give the same answer.
 */
class LightBufferTest {

    private static final RenderSettings SETTINGS = new RenderSettings(Shading.COOK_TORRANCE, 1, 0, 1e-9);
    private static final Material MATTE = Material.preset(MaterialType.MATTE);

    private static RenderScene scene(List<SceneObject> objects, Vector3d light) {
        return RenderScene.compile(new Scene(Camera.defaults(), Vector3d.ZERO, Vector3d.ZERO,
                List.of(new Light.Point(light, new Vector3d(1, 1, 1), 1)), objects), SETTINGS);
    }

    /**
     * The shadow ray from point p (offset along n) to the light: shadowed must agree with occluded.
     * Returns whether it is blocked.
     */
    private static boolean assertSameAnswer(RenderScene s, RayCaster caster, double[] p, double[] n, double offset,
                                            int skipCode) {
        double lx = s.lightVector[0] - p[0], ly = s.lightVector[1] - p[1], lz = s.lightVector[2] - p[2];
        double distance = Math.sqrt(lx * lx + ly * ly + lz * lz);
        double dx = lx / distance, dy = ly / distance, dz = lz / distance;
        double ox = p[0] + offset * n[0], oy = p[1] + offset * n[1], oz = p[2] + offset * n[2];
        boolean everySphere = caster.occluded(s, ox, oy, oz, dx, dy, dz, distance, skipCode);
        boolean listed = caster.shadowed(s, ox, oy, oz, dx, dy, dz, distance, skipCode, 0, offset);
        assertEquals(everySphere, listed, () -> String.format("point (%g, %g, %g) offset %g", p[0], p[1], p[2], offset));
        if (!caster.sphereMayShadow(s, dx, dy, dz, 0, offset, skipCode)) {
            assertEquals(everySphere, caster.anyPlaneBefore(s, ox, oy, oz, dx, dy, dz, distance, skipCode),
                    () -> String.format("planes only: point (%g, %g, %g) offset %g", p[0], p[1], p[2], offset));
        }
        return everySphere;
    }

    /** The largest offset for which the first light's cones or buffer answer for a shadow ray. */
    private static double maxOffset(RenderScene s) {
        return s.lightCones[0] != null ? s.lightCones[0].maxOffset : s.lightBuffers[0].maxOffset;
    }

    @Test
    void randomScenesAndPoints() {
        SplittableRandom random = new SplittableRandom(9);
        int blocked = 0, open = 0;
        for (int count : new int[] {1, 3, LightCones.MOST_SPHERES, 40, 400}) {
            for (int trial = 0; trial < 4; trial++) {
                List<SceneObject> objects = new ArrayList<>();
                double extent = Math.cbrt(count) * 3;
                for (int i = 0; i < count; i++) {
                    Vector3d centre = new Vector3d(random.nextDouble(-extent, extent), random.nextDouble(-extent, extent),
                            random.nextDouble(-extent, extent));
                    objects.add(new SceneObject(new Sphere(centre, random.nextDouble(0.1, 2)), MATTE));
                }
                objects.add(new SceneObject(new Plane(new Vector3d(0, -2 * extent, 0), new Vector3d(0, 1, 0)), MATTE));
                // the light anywhere: often inside a sphere or close to one in the smaller scenes
                Vector3d light = new Vector3d(random.nextDouble(-extent, extent), random.nextDouble(-extent, extent),
                        random.nextDouble(-extent, extent));
                RenderScene s = scene(objects, light);
                RayCaster caster = new RayCaster();
                for (int i = 0; i < 4000; i++) {
                    double[] p = {random.nextDouble(-2 * extent, 2 * extent), random.nextDouble(-2 * extent, 2 * extent),
                            random.nextDouble(-2 * extent, 2 * extent)};
                    double offset = i % 2 == 0 ? 1e-9 : maxOffset(s) * random.nextDouble(0, 2);
                    int skipped = random.nextInt(count + 1) - 1;
                    if (assertSameAnswer(s, caster, p, RandomScenes.unitVector(random), offset,
                            skipped < 0 ? 0 : RayCaster.surfaceId(skipped, -1))) {
                        blocked++;
                    } else {
                        open++;
                    }
                }
            }
        }
        assertTrue(blocked > 5000 && open > 5000, blocked + " blocked, " + open + " open");
    }

    /**
     * Shadow rays that graze a sphere close to the light, from far-off points offset as far as the
     * buffer allows: seen from the light they lie off their direction by up to the buffer's margin.
     */
    @Test
    void raysGrazingASphereNearTheLight() {
        raysGrazingASphereNearTheLight(30, new SplittableRandom(10)); // a light buffer
        raysGrazingASphereNearTheLight(2, new SplittableRandom(11)); // cones
    }

    private static void raysGrazingASphereNearTheLight(int others, SplittableRandom random) {
        int blocked = 0, open = 0;
        for (int trial = 0; trial < 50; trial++) {
            double radius = random.nextDouble(0.1, 1);
            double gap = random.nextDouble(1e-3, 0.1); // from the light to the sphere's surface
            double[] towards = RandomScenes.unitVector(random);
            double distance = radius + gap;
            Vector3d centre = new Vector3d(towards[0] * distance, towards[1] * distance, towards[2] * distance);
            List<SceneObject> objects = new ArrayList<>();
            objects.add(new SceneObject(new Sphere(centre, radius), MATTE));
            for (int i = 0; i < others; i++) { // others further out
                double[] u = RandomScenes.unitVector(random);
                double far = random.nextDouble(3, 20);
                objects.add(new SceneObject(new Sphere(new Vector3d(u[0] * far, u[1] * far, u[2] * far), 0.5), MATTE));
            }
            RenderScene s = scene(objects, Vector3d.ZERO);
            double maxOffset = maxOffset(s);
            assertTrue(maxOffset <= Math.sin(ConeCells.ANGLE_MARGIN) * gap * (1 + 1e-12));
            RayCaster caster = new RayCaster();
            // directions on the sphere's silhouette cone, turned in or out by up to twice the margin
            double halfAngle = Math.asin(radius / distance);
            for (int i = 0; i < 400; i++) {
                double angle = halfAngle + ConeCells.ANGLE_MARGIN * random.nextDouble(-2, 2);
                double[] dir = RandomScenes.atAngle(towards, angle, random);
                double reach = random.nextDouble(10, 1e4);
                double[] p = {dir[0] * reach, dir[1] * reach, dir[2] * reach};
                double offset = maxOffset * random.nextDouble(0.5, 1.0);
                if (assertSameAnswer(s, caster, p, RandomScenes.unitVector(random), offset, 0)) {
                    blocked++;
                } else {
                    open++;
                }
            }
        }
        assertTrue(blocked > 1000 && open > 1000, blocked + " blocked, " + open + " open");
    }

    @Test
    void aLightInsideASphereFindsItInEveryDirection() {
        List<SceneObject> objects = List.of(new SceneObject(new Sphere(new Vector3d(0, 0, 0), 2), MATTE),
                new SceneObject(new Sphere(new Vector3d(5, 0, 0), 1), MATTE));
        RenderScene s = scene(objects, new Vector3d(1.8, 0.2, 0));
        LightBuffer buffer = LightBuffer.build(s.spheres, 2, 1.8, 0.2, 0, Long.MAX_VALUE);
        SplittableRandom random = new SplittableRandom(3);
        for (int i = 0; i < 1000; i++) {
            double[] d = RandomScenes.unitVector(random);
            int cell = buffer.cell(d[0], d[1], d[2]);
            boolean listed = false;
            for (int j = buffer.cellStart[cell]; j < buffer.cellStart[cell + 1]; j++) {
                listed |= buffer.cellSpheres[j] == 0;
            }
            assertTrue(listed, "direction " + i);
        }
        // only the sphere outside limits the offsets
        assertEquals(Math.sin(ConeCells.ANGLE_MARGIN) * (Math.sqrt(3.2 * 3.2 + 0.2 * 0.2) - 1), buffer.maxOffset, 1e-15);
        assertEquals(buffer.maxOffset, s.lightCones[0].maxOffset, 1e-15);
    }

    /**
     * Every direction within a sphere's cone widened by the margin is listed, whichever cell it
     * falls in: also those just outside the sphere, which a shadow ray from an offset point may
     * need.
     */
    @Test
    void everyDirectionWithinTheWidenedConeIsListed() {
        SplittableRandom random = new SplittableRandom(12);
        for (int trial = 0; trial < 3000; trial++) {
            RandomScenes.SeenSphere seen = RandomScenes.SeenSphere.random(random);
            LightBuffer buffer = LightBuffer.build(seen.from(0, 0, 0), 1, 0, 0, 0, Long.MAX_VALUE);
            for (int i = 0; i < 100; i++) {
                double[] d = RandomScenes.atAngle(seen.towards(), seen.angleWithinMargin(i, random), random);
                int cell = buffer.cell(d[0], d[1], d[2]);
                assertEquals(1, buffer.cellStart[cell + 1] - buffer.cellStart[cell],
                        "trial " + trial + ", direction " + i);
            }
        }
    }

    /**
     * A scene of few spheres gets cones for every point light, and no buffer; one of more spheres
     * gets buffers for its first few point lights, within the memory budget, and no cones; past
     * those, shadow rays take the full test.
     */
    @Test
    void manyLightsOrCrowdedOnesGetNoBuffer() {
        List<Light> lights = new ArrayList<>();
        for (int i = 0; i < RenderScene.MOST_LIGHT_BUFFERS + 1; i++) {
            lights.add(new Light.Point(new Vector3d(i, 10, 0), new Vector3d(1, 1, 1), 1));
        }
        List<SceneObject> few = new ArrayList<>(), more = new ArrayList<>();
        for (int i = 0; i <= LightCones.MOST_SPHERES; i++) {
            (i < LightCones.MOST_SPHERES ? few : more).add(new SceneObject(new Sphere(new Vector3d(3 * i, 0, 0), 1), MATTE));
        }
        more.addAll(few);
        RenderScene withCones = RenderScene.compile(new Scene(Camera.defaults(), Vector3d.ZERO, Vector3d.ZERO, lights,
                few), SETTINGS);
        RenderScene many = RenderScene.compile(new Scene(Camera.defaults(), Vector3d.ZERO, Vector3d.ZERO, lights, more),
                SETTINGS);
        for (int i = 0; i <= RenderScene.MOST_LIGHT_BUFFERS; i++) {
            assertTrue(withCones.lightCones[i] != null, "light " + i);
            assertEquals(null, withCones.lightBuffers[i]);
            assertEquals(null, many.lightCones[i]);
        }
        for (int i = 0; i < RenderScene.MOST_LIGHT_BUFFERS; i++) {
            assertTrue(many.lightBuffers[i] != null, "light " + i);
        }
        assertEquals(null, many.lightBuffers[RenderScene.MOST_LIGHT_BUFFERS]);

        // nested spheres around the light: each is listed in every cell, past the budget
        int nested = (int) (RenderScene.LIGHT_BUFFER_ENTRIES / (LightBuffer.CELL_INDEX_SIZE - 1)) + 1;
        List<SceneObject> shells = new ArrayList<>();
        for (int i = 0; i < nested; i++) {
            shells.add(new SceneObject(new Sphere(new Vector3d(0, 0, 0), 1 + i), MATTE));
        }
        RenderScene crowded = scene(shells, new Vector3d(0.1, 0, 0));
        assertEquals(null, crowded.lightBuffers[0]);
        RayCaster caster = new RayCaster();
        assertTrue(caster.shadowed(crowded, 5.5, 0, 0, -1, 0, 0, 5.4, 0, 0, 1e-9));
        assertTrue(LightBuffer.build(crowded.spheres, nested, 0.1, 0, 0, Long.MAX_VALUE).entries()
                > RenderScene.LIGHT_BUFFER_ENTRIES);
    }

    @Test
    void aDirectionalLightHasNoConesOrBuffer() {
        RenderScene s = RenderScene.compile(new Scene(Camera.defaults(), Vector3d.ZERO, Vector3d.ZERO,
                List.of(new Light.Directional(new Vector3d(0, -1, 0), new Vector3d(1, 1, 1), 1)),
                List.of(new SceneObject(new Sphere(new Vector3d(0, 0, 0), 1), MATTE))), SETTINGS);
        assertEquals(null, s.lightBuffers[0]);
        assertEquals(null, s.lightCones[0]);
    }
}
