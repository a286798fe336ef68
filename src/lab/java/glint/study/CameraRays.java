package glint.study;

import glint.math.Quaternion;
import glint.math.Vector3d;

/**
 * Camera rays worked out in the model's own terms (a camera's orientation and field of view), apart
 * from the renderer's rows: the directions the studies trace and the tests check the renderer's
 * images against.
 */
public final class CameraRays {

    private CameraRays() {
    }

    /**
     * The unit direction of the camera ray through image point (px, py), in pixels from the
     * top-left corner of a width x height image (the centre of pixel (i, j) is (i + 0.5, j + 0.5)).
     * {@code fovDegrees} is the horizontal field of view; the vertical one follows from the aspect
     * ratio.
     */
    public static Vector3d direction(Quaternion orientation, double fovDegrees, int width, int height, double px,
                                     double py) {
        double tanHalf = Math.tan(Math.toRadians(fovDegrees) / 2);
        double sx = (2 * px / width - 1) * tanHalf;
        double sy = (1 - 2 * py / height) * tanHalf * height / width;
        Vector3d dir = orientation.forward()
                .add(orientation.right().scale(sx))
                .add(orientation.up().scale(sy));
        return dir.normalize();
    }
}
