package glint.ui.input;

import glint.accel.Aggregate;
import glint.geometry.Hit;
import glint.math.Vector3d;
import glint.render.PinholeCamera;
import glint.render.RenderScene;
import glint.scene.Camera;

/**
 * The point under the mouse: where the ray through its pixel meets the scene; what an orbit drag turns
 * around, and what a click focuses the lens on.
 */
public final class OrbitPivot {

    private OrbitPivot() {
    }

    /** The point under the pixel where the orbit drag of {@code in} started. */
    public static Vector3d pick(RenderScene scene, Camera camera, InputFrame in, int width, int height) {
        return pick(scene, camera, in.orbitFromX(), in.orbitFromY(), width, height);
    }

    /**
     * The nearest point of the scene on the camera's ray through pixel (x, y) of a width x height view (its
     * centre, as the tracer's); when the ray meets nothing, the point
     * {@link CameraController#ORBIT_MISS_DISTANCE} ahead of the camera, in the view's centre.
     */
    public static Vector3d pick(RenderScene scene, Camera camera, double x, double y, int width, int height) {
        Vector3d point = under(scene, camera, x, y, width, height);
        return point != null ? point
                : camera.position().add(camera.orientation().forward().scale(CameraController.ORBIT_MISS_DISTANCE));
    }

    /**
     * The nearest point of the scene on the ray through the centre of pixel (x, y) of a width x height view
     * from the camera's centre (a lens's central ray, the pinhole's), or null where it meets nothing (the sky).
     */
    public static Vector3d under(RenderScene scene, Camera camera, double x, double y, int width, int height) {
        PinholeCamera pinhole = new PinholeCamera(camera);
        Vector3d eye = pinhole.eye();
        Vector3d d = pinhole.direction(x + 0.5, y + 0.5, width, height);
        Aggregate aggregate = scene.aggregate();
        Hit hit = new Hit();
        if (aggregate.nearest(eye.x(), eye.y(), eye.z(), d.x(), d.y(), d.z(), Double.POSITIVE_INFINITY, Hit.NONE,
                Hit.NONE, hit, aggregate.newStack()) && Double.isFinite(hit.t)) {
            return eye.add(d.scale(hit.t));
        }
        return null;
    }
}
