package glint.math;

/** A ray: an origin and a unit direction, in world space. */
public record Ray(Vector3d origin, Vector3d direction) {

    public Vector3d at(double t) {
        return origin.add(direction.scale(t));
    }

    /**
     * The camera ray through image point (px, py), in pixels from the top-left corner of a
     * width x height image (the centre of pixel (i, j) is (i + 0.5, j + 0.5)). {@code fovDegrees}
     * is the horizontal field of view; the vertical one follows from the aspect ratio.
     */
    public static Ray calculateCameraRay(Vector3d eye, Quaternion orientation, double fovDegrees,
                                         int width, int height, double px, double py) {
        double tanHalf = Math.tan(Math.toRadians(fovDegrees) / 2);
        double sx = (2 * px / width - 1) * tanHalf;
        double sy = (1 - 2 * py / height) * tanHalf * height / width;
        Vector3d dir = orientation.forward()
                .add(orientation.right().scale(sx))
                .add(orientation.up().scale(sy));
        return new Ray(eye, dir.normalize());
    }
}
