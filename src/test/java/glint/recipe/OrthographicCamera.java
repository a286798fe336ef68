package glint.recipe;

import glint.math.Quaternion;
import glint.math.Vector3d;
import glint.render.CameraModel;
import glint.scene.Camera;
import java.util.Optional;

/**
 * A camera added by the camera recipe of docs/architecture.md, in test sources only: an orthographic
 * camera, whose rays all travel along the view direction from a window of {@code span} scene units
 * across, centred on the camera's position and facing the way it looks; a film point (px, py) of a
 * width x height image leaves the window at position + (px / width - 1/2) span right + (1/2 - py /
 * width) span up (square pixels). Its lens point is ignored. Its rays leave different points.
 */
record OrthographicCamera(Vector3d position, Vector3d right, Vector3d up, Vector3d forward, double span)
        implements CameraModel {

    static OrthographicCamera of(Camera camera, double span) {
        Quaternion q = camera.orientation();
        return new OrthographicCamera(camera.position(), q.right(), q.up(), q.forward(), span);
    }

    @Override
    public boolean oneOrigin() {
        return false;
    }

    @Override
    public Vector3d eye() {
        return position;
    }

    @Override
    public void ray(double px, double py, double lensU, double lensV, int width, int height, double[] ox,
                    double[] oy, double[] oz, double[] dx, double[] dy, double[] dz, int i) {
        double x = (px / width - 0.5) * span, y = (0.5 * height - py) / width * span;
        ox[i] = position.x() + x * right.x() + y * up.x();
        oy[i] = position.y() + x * right.y() + y * up.y();
        oz[i] = position.z() + x * right.z() + y * up.z();
        dx[i] = forward.x();
        dy[i] = forward.y();
        dz[i] = forward.z();
    }

    /** Where p lies across the window, for a point in front of its plane. */
    @Override
    public Optional<ImagePoint> imagePoint(Vector3d p, int width, int height) {
        Vector3d v = p.sub(position);
        if (!(v.dot(forward) > 0)) {
            return Optional.empty();
        }
        double x = v.dot(right) / span, y = v.dot(up) / span;
        return Optional.of(new ImagePoint((x + 0.5) * width, 0.5 * height - y * width));
    }
}
