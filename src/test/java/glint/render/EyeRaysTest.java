package glint.render;

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

/**
 * A camera ray tests only the spheres its pixel can show, and still meets what testing every
 * sphere and plane from the eye meets: the same distance, the same surface.
 */
class EyeRaysTest {

    private static final RenderSettings SETTINGS = new RenderSettings(Shading.COOK_TORRANCE, 1, 0, 1e-9);
    private static final Material MATTE = Material.preset(MaterialType.MATTE);

    /** Checks every camera ray of a width x height frame in divider x divider tiles; returns how many met a sphere. */
    private static int assertEveryCameraRayMeetsWhatBruteForceMeets(RenderScene s, int width, int height,
                                                                     int samples, int divider) {
        RayCaster caster = new RayCaster();
        CameraRows rows = new CameraRows();
        int sphereHits = 0;
        for (int tile = 0; tile < divider * divider; tile++) {
            int x0 = tile % divider * width / divider, x1 = (tile % divider + 1) * width / divider;
            int y0 = tile / divider * height / divider, y1 = (tile / divider + 1) * height / divider;
            rows.prepare(s.camera, width, height, x0, x1, samples, 0, samples, 0);
            caster.eye.prepare(s);
            caster.eye.aimTile(rows.screenX(x0), rows.screenX(x1), rows.screenY(y1), rows.screenY(y0));
            for (int y = y0; y < y1; y++) {
                caster.eye.aimRow(rows.screenY(y + 1), rows.screenY(y));
                rows.aim(y);
                for (int x = x0; x < x1; x++) {
                    caster.eye.aimPixel(rows.screenX(x), rows.screenX(x + 1));
                    for (int ray = (x - x0) * samples; ray < (x - x0 + 1) * samples; ray++) {
                        double dx = rows.dirX[ray], dy = rows.dirY[ray], dz = rows.dirZ[ray];
                        EverySurface.Hit expected = EverySurface.nearest(s, s.camera.eyeX, s.camera.eyeY,
                                s.camera.eyeZ, dx, dy, dz, -1, -1);
                        boolean found = caster.nearestFromEye(s, dx, dy, dz);
                        String where = "pixel " + x + "," + y + " ray " + ray;
                        assertEquals(expected.t() < Intersect.MISS, found, where);
                        assertEquals(expected.t(), caster.hitT, 0, where);
                        assertEquals(expected.sphere(), caster.hitSphere, where);
                        assertEquals(expected.plane(), caster.hitPlane, where);
                        sphereHits += expected.sphere() >= 0 ? 1 : 0;
                    }
                }
            }
        }
        return sphereHits;
    }

    private static RenderScene compile(Camera camera, List<SceneObject> objects) {
        return RenderScene.compile(new Scene(camera, Vector3d.ZERO, Vector3d.ZERO, List.of(), objects), SETTINGS);
    }

    @Test
    void randomScenesWithAndWithoutAHierarchy() {
        SplittableRandom random = new SplittableRandom(42);
        int sphereHits = 0;
        for (int count : new int[] {1, 3, 6, 40, 400}) {
            for (int trial = 0; trial < 3; trial++) {
                List<SceneObject> objects = new ArrayList<>();
                double extent = Math.cbrt(count) * 2;
                for (int i = 0; i < count; i++) {
                    // some spheres reach behind the eye (at the origin) or hold it
                    Vector3d centre = new Vector3d(random.nextDouble(-extent, extent), random.nextDouble(-extent, extent),
                            random.nextDouble(-extent, 3 * extent));
                    objects.add(new SceneObject(new Sphere(centre, random.nextDouble(0.05, 1.5)), MATTE));
                }
                objects.add(new SceneObject(new Plane(new Vector3d(0, -extent, 0), new Vector3d(0, 1, 0)), MATTE));
                Vector3d look = new Vector3d(random.nextDouble(-1, 1), random.nextDouble(-1, 1), 1);
                Camera camera = Camera.lookAt(Vector3d.ZERO, look, new Vector3d(0, 1, 0), random.nextDouble(20, 120));
                int samples = trial == 0 ? 1 : 4;
                sphereHits += assertEveryCameraRayMeetsWhatBruteForceMeets(compile(camera, objects), 37, 29, samples,
                        1 + trial * 2);
            }
        }
        assertTrue(sphereHits > 5000, sphereHits + " rays met a sphere");
    }

    /**
     * One row 20,000 pixels wide, then one column 20,000 high, through spheres seen from all sides:
     * the pixels at their silhouettes, a ten-thousandth of the view apart, show them too.
     */
    @Test
    void silhouettesAreNotCulled() {
        SplittableRandom random = new SplittableRandom(5);
        List<SceneObject> objects = new ArrayList<>();
        for (int i = 0; i < 5; i++) {
            Vector3d centre = new Vector3d(random.nextDouble(-3, 3), random.nextDouble(-0.2, 0.2), random.nextDouble(3, 9));
            objects.add(new SceneObject(new Sphere(centre, random.nextDouble(0.3, 1)), MATTE));
        }
        Camera camera = Camera.lookAt(Vector3d.ZERO, new Vector3d(0, 0, 1), new Vector3d(0, 1, 0), 90);
        assertTrue(assertEveryCameraRayMeetsWhatBruteForceMeets(compile(camera, objects), 20_000, 1, 1, 1) > 1000);
        // the field of view is across: a column one pixel wide and 90 degrees high has a tiny one
        double across = Math.toDegrees(2 * Math.atan(1 / 20_000.0));
        Camera turned = Camera.lookAt(Vector3d.ZERO, new Vector3d(0, 0, 1), new Vector3d(1, 0, 0), across);
        assertTrue(assertEveryCameraRayMeetsWhatBruteForceMeets(compile(turned, objects), 1, 20_000, 1, 1) > 1000);
    }

    /** A row of spheres along the view: a pixel shows more than the sweep takes, and the hierarchy finds the nearest. */
    @Test
    void spheresBehindOneAnotherOnScreen() {
        List<SceneObject> objects = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            objects.add(new SceneObject(new Sphere(new Vector3d(0.02 * (i % 3), 0, 5 + 1.5 * i), 0.7 + 0.01 * i), MATTE));
        }
        Camera camera = Camera.lookAt(Vector3d.ZERO, new Vector3d(0, 0, 1), new Vector3d(0, 1, 0), 40);
        RenderScene scene = compile(camera, objects);
        assertTrue(scene.hasHierarchy());
        assertTrue(assertEveryCameraRayMeetsWhatBruteForceMeets(scene, 31, 31, 1, 2) > 100);
        // the centre pixel shows every sphere: more than a sweep takes
        RayCaster caster = new RayCaster();
        CameraRows rows = new CameraRows();
        rows.prepare(scene.camera, 31, 31, 0, 31, 1, 0, 1, 0);
        caster.eye.prepare(scene);
        caster.eye.aimTile(rows.screenX(0), rows.screenX(31), rows.screenY(31), rows.screenY(0));
        caster.eye.aimRow(rows.screenY(16), rows.screenY(15));
        caster.eye.aimPixel(rows.screenX(15), rows.screenX(16));
        assertEquals(40, caster.eye.pixelCount);
        assertTrue(caster.eye.pixelCount > RayCaster.MOST_SPHERES_SWEPT);
    }
}
