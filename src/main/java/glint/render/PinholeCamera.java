package glint.render;

import glint.math.Quaternion;
import glint.math.Vector3d;
import glint.scene.Camera;
import java.util.Optional;

/**
 * The pinhole camera (aperture 0; {@link CameraModel}): every ray from the eye, compiled from the scene's
 * {@link Camera} (world space). A ray goes from the eye through a point of the screen, the image
 * plane one unit ahead: screen (sx, sy) is the direction forward + sx right + sy up, made unit.
 * A width x height image covers the screen from sx = -tan(fov / 2) on its left to +tan(fov / 2) on
 * its right (fov is the horizontal field of view; +x on the image's right when looking along +z
 * with up +y), and the height in proportion, sy growing upwards. Image point (px, py) is in pixels
 * from the image's top-left corner; the centre of pixel (i, j) is (i + 0.5, j + 0.5). The ray through
 * an image point is {@link #direction}; the image point a world point is seen at, {@link #imagePoint}.
 *
 * <p>Every ray leaves the same point, the {@link #eye()} ({@link #oneOrigin}). The row search relies on
 * it ({@link CameraRows}): a tile row's rays lie in one frustum from the eye, the primitives it may
 * hold are searched from that one origin ({@code PrimitiveKind.nearestFromOrigin}), and a box is
 * narrowed to the rays between the screen x of its corners as seen from the eye. Its film points map
 * onto the screen as {@link ThinLensCamera}'s do; its lens point is ignored.
 */
public final class PinholeCamera implements CameraModel {

    private final double eyeX, eyeY, eyeZ;
    private final double rightX, rightY, rightZ;
    private final double upX, upY, upZ;
    private final double forwardX, forwardY, forwardZ;
    /** tan(fov / 2): half the screen's width. */
    private final double tanHalfFov;

    public PinholeCamera(Camera camera) {
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

    /** True: every ray leaves the eye. */
    @Override
    public boolean oneOrigin() {
        return true;
    }

    /** The point every ray of this camera leaves. */
    @Override
    public Vector3d eye() {
        return new Vector3d(eyeX, eyeY, eyeZ);
    }

    /**
     * The unit direction of the ray through image point (px, py) of a width x height image: the
     * arithmetic of the renderer's rays, bit for bit. Allocates; the renderer aims through
     * {@link #aim} instead.
     */
    public Vector3d direction(double px, double py, int width, int height) {
        double sx = screen(px, screenPerPixelX(width), screenLeft());
        double sy = screen(py, screenPerPixelY(width, height), screenTop(width, height));
        double[] x = new double[1], y = new double[1], z = new double[1];
        aim(sx, sy, x, y, z, 0);
        return new Vector3d(x[0], y[0], z[0]);
    }

    /**
     * The image point (px, py) of a width x height image at which world point {@code p} is seen: the inverse
     * of {@link #direction}, whose ray through it meets {@code p}. Empty for a point on or behind the plane of
     * the eye (facing the way the camera looks), which no camera ray meets; a point outside the field of view
     * has a point outside [0, width] x [0, height]. Allocates: for tests and tools, not the per-pixel path.
     */
    @Override
    public Optional<ImagePoint> imagePoint(Vector3d p, int width, int height) {
        double dx = p.x() - eyeX, dy = p.y() - eyeY, dz = p.z() - eyeZ;
        double ahead = dx * forwardX + dy * forwardY + dz * forwardZ;
        if (!(ahead > 0)) {
            return Optional.empty();
        }
        double sx = (dx * rightX + dy * rightY + dz * rightZ) / ahead; // on the screen one unit ahead
        double sy = (dx * upX + dy * upY + dz * upZ) / ahead;
        return Optional.of(new ImagePoint((sx - screenLeft()) / screenPerPixelX(width),
                (sy - screenTop(width, height)) / screenPerPixelY(width, height)));
    }

    /** The ray from the eye through film point (px, py), whatever the lens point: {@link #direction}'s arithmetic. */
    @Override
    public void ray(double px, double py, double lensU, double lensV, int width, int height, double[] ox,
                    double[] oy, double[] oz, double[] dx, double[] dy, double[] dz, int i) {
        ox[i] = eyeX;
        oy[i] = eyeY;
        oz[i] = eyeZ;
        aim(screen(px, screenPerPixelX(width), screenLeft()),
                screen(py, screenPerPixelY(width, height), screenTop(width, height)), dx, dy, dz, i);
    }

    /** 1 / (A cos^3 theta) where d's screen point lies on the image; o is the eye. */
    @Override
    public double directionPdf(double ox, double oy, double oz, double dx, double dy, double dz, int width,
                               int height) {
        return throughLens(dx, dy, dz, 0, 0, 1, width, height);
    }

    /**
     * 1 / (A cos^3 theta) for a ray along unit d from a lens point (lx, ly) off the eye along right and up,
     * through a lens focused at {@code focus}, where its film point (the pinhole's, shifted by l / focus)
     * lies on the image; 0 elsewhere.
     */
    double throughLens(double dx, double dy, double dz, double lx, double ly, double focus, int width,
                       int height) {
        double cos = dx * forwardX + dy * forwardY + dz * forwardZ;
        if (!(cos > 0)) {
            return 0;
        }
        return importance((dx * rightX + dy * rightY + dz * rightZ) / cos + lx / focus,
                (dx * upX + dy * upY + dz * upZ) / cos + ly / focus, cos, width, height);
    }

    @Override
    public boolean sees(double px, double py, double pz, double lensU, double lensV, int width, int height,
                        CameraSight out) {
        return seenFrom(eyeX, eyeY, eyeZ, 0, 0, 1, px, py, pz, width, height, out);
    }

    /**
     * Fills {@code out} for world point p seen from lens point l, which lies (lx, ly) off the eye along
     * right and up, through a lens focused at {@code focus} (any value where lx = ly = 0): false where p
     * is not ahead of l or its film point is off the image.
     */
    boolean seenFrom(double lX, double lY, double lZ, double lx, double ly, double focus, double px, double py,
                     double pz, int width, int height, CameraSight out) {
        double vx = px - lX, vy = py - lY, vz = pz - lZ;
        double ahead = vx * forwardX + vy * forwardY + vz * forwardZ;
        if (!(ahead > 0)) {
            return false;
        }
        // the screen point of the film point whose ray from l meets p: the pinhole's, shifted by l / focus
        double sx = (vx * rightX + vy * rightY + vz * rightZ) / ahead + lx / focus;
        double sy = (vx * upX + vy * upY + vz * upZ) / ahead + ly / focus;
        out.filmX = (sx - screenLeft()) / screenPerPixelX(width);
        out.filmY = (sy - screenTop(width, height)) / screenPerPixelY(width, height);
        if (!(out.filmX >= 0 && out.filmX < width && out.filmY >= 0 && out.filmY < height)) {
            return false;
        }
        out.set(px, py, pz, lX, lY, lZ);
        double cos = ahead / out.distance;
        out.importance = 1 / (screenArea(width, height) * cos * cos * cos);
        return true;
    }

    /**
     * 1 / (A cos^3) for a ray at cosine {@code cos} to the view direction whose film point has screen point
     * (sx, sy); 0 where that point is off the image.
     */
    double importance(double sx, double sy, double cos, int width, int height) {
        double top = screenTop(width, height);
        if (!(Math.abs(sx) <= tanHalfFov && Math.abs(sy) <= top)) {
            return 0;
        }
        return 1 / (screenArea(width, height) * cos * cos * cos);
    }

    /** The area of the screen one unit ahead that a width x height image covers. */
    double screenArea(int width, int height) {
        return 2 * tanHalfFov * 2 * screenTop(width, height);
    }

    // ---------------------------------------------------------------- the image on the screen

    /** Screen coordinate of image coordinate p: the screen per pixel times p, plus the screen at p = 0. */
    static double screen(double p, double perPixel, double edge) {
        return p * perPixel + edge;
    }

    /** Screen x per pixel of an image {@code width} pixels wide. */
    double screenPerPixelX(int width) {
        return 2 * tanHalfFov / width;
    }

    /** Screen x of the image's left edge. */
    double screenLeft() {
        return -tanHalfFov;
    }

    /** Screen y per pixel (downwards: negative) of a width x height image. */
    double screenPerPixelY(int width, int height) {
        return -2 * screenTop(width, height) / height;
    }

    /** Screen y of the top edge of a width x height image. */
    double screenTop(int width, int height) {
        return tanHalfFov * height / width;
    }

    // ---------------------------------------------------------------- rays

    /**
     * Stores the unit direction of the ray through screen point (sx, sy) into (outX[i], outY[i], outZ[i]).
     */
    void aim(double sx, double sy, double[] outX, double[] outY, double[] outZ, int i) {
        double dx = forwardX + sx * rightX + sy * upX;
        double dy = forwardY + sx * rightY + sy * upY;
        double dz = forwardZ + sx * rightZ + sy * upZ;
        double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
        outX[i] = dx * inv;
        outY[i] = dy * inv;
        outZ[i] = dz * inv;
    }

    /**
     * Stores the unit directions of the rays through screen points (screenX[i], sy), i in [0, n),
     * one row of the screen, into out[i]: the arithmetic of {@link #aim}, with what the row shares
     * worked out once.
     */
    void aimRow(double[] screenX, int n, double sy, double[] outX, double[] outY, double[] outZ) {
        double rowUpX = sy * upX, rowUpY = sy * upY, rowUpZ = sy * upZ;
        double fX = forwardX, fY = forwardY, fZ = forwardZ;
        double rX = rightX, rY = rightY, rZ = rightZ;
        for (int i = 0; i < n; i++) {
            double sx = screenX[i];
            double dx = fX + sx * rX + rowUpX;
            double dy = fY + sx * rY + rowUpY;
            double dz = fZ + sx * rZ + rowUpZ;
            double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
            outX[i] = dx * inv;
            outY[i] = dy * inv;
            outZ[i] = dz * inv;
        }
    }

    /** Stores the direction (not unit) through screen point (sx, sy) into out[at], out[at + 1], out[at + 2]. */
    void through(double sx, double sy, double[] out, int at) {
        out[at] = forwardX + sx * rightX + sy * upX;
        out[at + 1] = forwardY + sx * rightY + sy * upY;
        out[at + 2] = forwardZ + sx * rightZ + sy * upZ;
    }

    // ---------------------------------------------------------------- what the row search reads:
    // the eye every ray leaves, and the axes it projects a box onto the screen with (CameraRows.narrow)

    double eyeX() {
        return eyeX;
    }

    double eyeY() {
        return eyeY;
    }

    double eyeZ() {
        return eyeZ;
    }

    double forwardX() {
        return forwardX;
    }

    double forwardY() {
        return forwardY;
    }

    double forwardZ() {
        return forwardZ;
    }

    double rightX() {
        return rightX;
    }

    double rightY() {
        return rightY;
    }

    double rightZ() {
        return rightZ;
    }

    double upX() {
        return upX;
    }

    double upY() {
        return upY;
    }

    double upZ() {
        return upZ;
    }
}
