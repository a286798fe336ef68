package glint.scene;

import glint.math.Quaternion;
import glint.math.Vector3d;

/**
 * Where the camera is, which way it faces (a unit quaternion), its horizontal field of view, and its lens:
 * {@code aperture}, the lens radius in scene units (0: a pinhole, everything sharp), and {@code focus}, the
 * distance from the camera to the plane in focus, along the view direction (it matters only when the
 * aperture is above 0).
 */
public record Camera(Vector3d position, Quaternion orientation, double fovDegrees, double aperture,
                     double focus) {

    public static final double DEFAULT_FOV = 60;
    /**
     * The focus of a camera given no look_at and no focus: one unit, the distance of the look_at a camera
     * without one gets (one unit ahead).
     */
    public static final double DEFAULT_FOCUS = 1;

    /** A pinhole camera: aperture 0, focus {@link #DEFAULT_FOCUS}. */
    public Camera(Vector3d position, Quaternion orientation, double fovDegrees) {
        this(position, orientation, fovDegrees, 0, DEFAULT_FOCUS);
    }

    /** A pinhole camera at {@code position} looking at {@code lookAt}, focused on it (focus = their distance). */
    public static Camera lookAt(Vector3d position, Vector3d lookAt, Vector3d up, double fovDegrees) {
        Vector3d view = lookAt.sub(position);
        return new Camera(position, Quaternion.lookRotation(view, up), fovDegrees, 0, view.length());
    }

    public static Camera defaults() {
        Vector3d position = new Vector3d(0, 1, -5);
        return lookAt(position, position.add(Vector3d.UNIT_Z), Vector3d.UNIT_Y, DEFAULT_FOV);
    }

    /** The same camera (field of view and lens) at another pose. */
    public Camera withPose(Vector3d newPosition, Quaternion newOrientation) {
        return new Camera(newPosition, newOrientation, fovDegrees, aperture, focus);
    }

    /** The same camera with another lens: aperture (radius) and focus distance in scene units. */
    public Camera withLens(double newAperture, double newFocus) {
        return new Camera(position, orientation, fovDegrees, newAperture, newFocus);
    }
}
