package glint.study;

import glint.math.Quaternion;
import glint.math.Vector3d;
import glint.render.PinholeCamera;
import glint.scene.Camera;

/**
 * A pinhole view of one sphere: the n x n pixel-centre rays of Glint's camera at {@code eye}, oriented
 * by forward and up, with a horizontal field of view of {@code fovDegrees}.
 */
public record SphereView(Vector3d center, double radius, Vector3d eye, Vector3d forward, Vector3d up,
                         double fovDegrees, int n) {

    /** Tolerance on the hit distance: 0.1 % of the smaller of the radius and the true distance. */
    public static final double DISTANCE_TOLERANCE = 1e-3;

    /**
     * A unit sphere at {@code distance} from a camera at the origin, looking at it along an
     * oblique axis (every coordinate non-zero); the disc spans 80 % of the image width.
     */
    public static SphereView farSphere(double distance, int n) {
        Vector3d axis = new Vector3d(0.3, 0.2, 1).normalize();
        double sinAngular = 1 / distance;
        double tanAngular = sinAngular / Math.sqrt(1 - sinAngular * sinAngular);
        return new SphereView(axis.scale(distance), 1, Vector3d.ZERO, axis, Vector3d.UNIT_Y,
                Math.toDegrees(2 * Math.atan(1.25 * tanAngular)), n);
    }

    /**
     * A sphere of {@code radius} below a camera one unit above its top, looking 15 degrees down:
     * the sphere is the ground, its horizon crosses the upper part of the image (a 60 degree view).
     */
    public static SphereView hugeSphere(double radius, int n) {
        Vector3d forward = new Vector3d(0, -Math.sin(Math.toRadians(15)), Math.cos(Math.toRadians(15)));
        return new SphereView(new Vector3d(0, -radius, 0), radius, Vector3d.UNIT_Y, forward, Vector3d.UNIT_Y,
                60, n);
    }

    /** Unit direction (double) of the ray through the centre of pixel (x, y), rows top to bottom. */
    public double[] direction(int x, int y) {
        Vector3d d = new PinholeCamera(new Camera(eye, Quaternion.lookRotation(forward, up), fovDegrees))
                .direction(x + 0.5, y + 0.5, n, n);
        return new double[] {d.x(), d.y(), d.z()};
    }
}
