package glint.study;

import glint.math.Quaternion;
import glint.math.Vector3d;

/**
 * A pinhole view of one sphere: n x n pixel-centre rays from {@code eye} with horizontal half-angle
 * tangent {@code tanHalf}, oriented by forward and up as Glint's camera is.
 */
public record SphereView(Vector3d center, double radius, Vector3d eye, Vector3d forward, Vector3d up,
                         double tanHalf, int n) {

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
                1.25 * tanAngular, n);
    }

    /**
     * A sphere of {@code radius} below a camera one unit above its top, looking 15 degrees down:
     * the sphere is the ground, its horizon crosses the upper part of the image (a 60 degree view).
     */
    public static SphereView hugeSphere(double radius, int n) {
        Vector3d forward = new Vector3d(0, -Math.sin(Math.toRadians(15)), Math.cos(Math.toRadians(15)));
        return new SphereView(new Vector3d(0, -radius, 0), radius, Vector3d.UNIT_Y, forward, Vector3d.UNIT_Y,
                Math.tan(Math.toRadians(30)), n);
    }

    /** Unit direction (double) of the ray through the centre of pixel (x, y), rows top to bottom. */
    public double[] direction(int x, int y) {
        Quaternion q = Quaternion.lookRotation(forward, up);
        Vector3d f = q.forward(), r = q.right(), u = q.up();
        double sx = ((x + 0.5) / n * 2 - 1) * tanHalf;
        double sy = (1 - (y + 0.5) / n * 2) * tanHalf;
        Vector3d d = f.add(r.scale(sx)).add(u.scale(sy)).normalize();
        return new double[] {d.x(), d.y(), d.z()};
    }
}
