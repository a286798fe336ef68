package glint.scene;

import glint.math.Quaternion;
import glint.math.Vector3d;

/** Where the camera is, which way it faces (a unit quaternion) and its horizontal field of view. */
public record Camera(Vector3d position, Quaternion orientation, double fovDegrees) {

    public static final double DEFAULT_FOV = 60;

    public static Camera lookAt(Vector3d position, Vector3d lookAt, Vector3d up, double fovDegrees) {
        return new Camera(position, Quaternion.lookRotation(lookAt.sub(position), up), fovDegrees);
    }

    public static Camera defaults() {
        Vector3d position = new Vector3d(0, 1, -5);
        return lookAt(position, position.add(Vector3d.UNIT_Z), Vector3d.UNIT_Y, DEFAULT_FOV);
    }

    public Camera withPose(Vector3d newPosition, Quaternion newOrientation) {
        return new Camera(newPosition, newOrientation, fovDegrees);
    }
}
