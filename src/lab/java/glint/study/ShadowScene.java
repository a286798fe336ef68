package glint.study;

import glint.math.Vector3d;
import glint.registry.MatteType;
import glint.render.PinholeCamera;
import glint.scene.Camera;
import glint.scene.Light;
import glint.scene.Material;
import glint.scene.Plane;
import glint.scene.Scene;
import glint.scene.SceneObject;
import glint.scene.Sphere;
import java.util.ArrayList;
import java.util.List;

/**
 * A matte scene lit by one point light, for the self-intersection study: spheres (centre x, y, z,
 * radius), optionally the floor plane y = floorY, a camera. It can be moved by (s, s, s) and turned
 * into a Glint scene; its pixel rays are Glint's (pixel centres, {@link PinholeCamera#direction}).
 */
public record ShadowScene(List<double[]> spheres, boolean hasFloor, double floorY, Vector3d light,
                          Vector3d eye, Vector3d lookAt, double fovDegrees, int width, int height) {

    /** Light intensity: a lit white matte point at distance ~8 gets radiance ~0.5. */
    public static final double LIGHT_INTENSITY = 100;

    /**
     * Contact shadows: a unit ball and a pebble of radius 0.25 resting on the floor, the light high
     * to the left and behind, so both cast shadows that start at their contact points.
     */
    public static ShadowScene contact(int width, int height) {
        List<double[]> spheres = List.of(new double[] {0, 1, 0, 1}, new double[] {-1.7, 0.25, -1.3, 0.25});
        return new ShadowScene(spheres, true, 0, new Vector3d(-4, 6, 2), new Vector3d(0.5, 3.2, -6.5),
                new Vector3d(0, 0.3, -0.3), 45, width, height);
    }

    /**
     * A ground sphere of the given radius, its top at the origin, seen from 1.5 units above it:
     * large radii with small coordinates (the offset rule scales with |p|, not with the radius).
     */
    public static ShadowScene groundSphere(double radius, int width, int height) {
        List<double[]> spheres = List.<double[]>of(new double[] {0, -radius, 0, radius});
        return new ShadowScene(spheres, false, 0, new Vector3d(1, 6, 2), new Vector3d(0, 1.5, -2),
                new Vector3d(0, 0, 1), 60, width, height);
    }

    /** The same scene moved by (s, s, s): camera, light and every shape. */
    public ShadowScene translated(double s) {
        Vector3d shift = new Vector3d(s, s, s);
        List<double[]> moved = new ArrayList<>();
        for (double[] sp : spheres) {
            moved.add(new double[] {sp[0] + s, sp[1] + s, sp[2] + s, sp[3]});
        }
        return new ShadowScene(moved, hasFloor, floorY + s, light.add(shift), eye.add(shift), lookAt.add(shift),
                fovDegrees, width, height);
    }

    public Camera camera() {
        return Camera.lookAt(eye, lookAt, Vector3d.UNIT_Y, fovDegrees);
    }

    /** Unit direction of the ray through the centre of pixel (x, y); the same for a moved scene. */
    public double[] direction(int x, int y) {
        Vector3d d = new PinholeCamera(camera()).direction(x + 0.5, y + 0.5, width, height);
        return new double[] {d.x(), d.y(), d.z()};
    }

    /** As a Glint scene: white matte everywhere, black background, no ambient light. */
    public Scene toScene() {
        Material white = new Material(MatteType.TYPE.name(), Vector3d.ONE, 0.99, 0.01, 0, 10);
        List<SceneObject> objects = new ArrayList<>();
        for (double[] sp : spheres) {
            objects.add(new SceneObject(new Sphere(new Vector3d(sp[0], sp[1], sp[2]), sp[3]), white));
        }
        if (hasFloor) {
            objects.add(new SceneObject(new Plane(new Vector3d(0, floorY, 0), Vector3d.UNIT_Y), white));
        }
        return new Scene(camera(), Vector3d.ZERO, Vector3d.ZERO,
                List.of(new Light.Point(light, Vector3d.ONE, LIGHT_INTENSITY)), objects);
    }
}
