package glint.render;

import glint.math.Quaternion;
import glint.math.Vector3d;
import glint.scene.Camera;

/** The camera as the tracer uses it: the eye and the unit right, up and forward axes (world space). */
final class CameraBasis {

    final double eyeX, eyeY, eyeZ;
    final double rightX, rightY, rightZ;
    final double upX, upY, upZ;
    final double forwardX, forwardY, forwardZ;
    /** tan(fov / 2): half the image plane's width at distance 1. */
    final double tanHalfFov;

    CameraBasis(Camera camera) {
        Quaternion q = camera.orientation();
        Vector3d right = q.right(), up = q.up(), forward = q.forward();
        eyeX = camera.position().x();
        eyeY = camera.position().y();
        eyeZ = camera.position().z();
        rightX = right.x();
        rightY = right.y();
        rightZ = right.z();
        upX = up.x();
        upY = up.y();
        upZ = up.z();
        forwardX = forward.x();
        forwardY = forward.y();
        forwardZ = forward.z();
        tanHalfFov = Math.tan(Math.toRadians(camera.fovDegrees()) / 2);
    }
}
