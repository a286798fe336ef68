package glint.render;

import glint.math.Vector3d;
import glint.scene.Camera;
import java.util.Optional;

/**
 * A thin lens (world space), compiled from a scene {@link Camera} whose aperture is above 0: a disc of
 * radius {@code aperture} centred on the camera's position, facing the way it looks, focused on the plane
 * {@code focus} ahead of it, perpendicular to the view direction. A film point maps onto the screen as the
 * {@link PinholeCamera} at the lens centre maps it, screen point s = (sx, sy); the point of the plane in
 * focus it sees is c + focus (forward + sx right + sy up), where the pinhole's ray through s meets that
 * plane. A lens point (u, v) in [0, 1)^2 is mapped onto the unit disc by the concentric map (Shirley and
 * Chiu 1997), (lx, ly), and the ray leaves o = c + aperture (lx right + ly up) towards that point of the
 * plane in focus:
 *
 * <pre>  d = normalize(focus (forward + sx right + sy up) - aperture (lx right + ly up))</pre>
 *
 * so every ray of one film point meets in focus, and a point at depth z off that plane blurs into a disc of
 * diameter 2 aperture |1 - z / focus| in its own plane (2 aperture |1 - focus / z| in the plane in focus:
 * the circle of confusion). Its rays leave different
 * points, so a tile row's are searched ray by ray. A world point is seen where the ray through the lens
 * centre sees it ({@link #imagePoint}, the pinhole's).
 */
public final class ThinLensCamera implements CameraModel {

    /** The pinhole at the lens centre: the film's map onto the screen, the centre's rays and image points. */
    private final PinholeCamera centre;
    private final double eyeX, eyeY, eyeZ;
    private final double rightX, rightY, rightZ;
    private final double upX, upY, upZ;
    private final double forwardX, forwardY, forwardZ;
    /** The lens radius and the distance of the plane in focus along the view direction, scene units. */
    private final double aperture, focus;

    public ThinLensCamera(Camera camera) {
        centre = new PinholeCamera(camera);
        eyeX = centre.eyeX();
        eyeY = centre.eyeY();
        eyeZ = centre.eyeZ();
        rightX = centre.rightX();
        rightY = centre.rightY();
        rightZ = centre.rightZ();
        upX = centre.upX();
        upY = centre.upY();
        upZ = centre.upZ();
        forwardX = centre.forwardX();
        forwardY = centre.forwardY();
        forwardZ = centre.forwardZ();
        aperture = camera.aperture();
        focus = camera.focus();
    }

    /** False: rays leave the whole lens. */
    @Override
    public boolean oneOrigin() {
        return false;
    }

    /** The centre of the lens. */
    @Override
    public Vector3d eye() {
        return centre.eye();
    }

    @Override
    public void ray(double px, double py, double lensU, double lensV, int width, int height, double[] ox,
                    double[] oy, double[] oz, double[] dx, double[] dy, double[] dz, int i) {
        double sx = PinholeCamera.screen(px, centre.screenPerPixelX(width), centre.screenLeft());
        double sy = PinholeCamera.screen(py, centre.screenPerPixelY(width, height), centre.screenTop(width, height));
        double a = 2 * lensU - 1, b = 2 * lensV - 1; // the square [-1, 1)^2
        double radius = aperture * discRadius(a, b), angle = discAngle(a, b);
        double lx = radius * Math.cos(angle), ly = radius * Math.sin(angle); // on the lens, scene units
        double offX = lx * rightX + ly * upX, offY = lx * rightY + ly * upY, offZ = lx * rightZ + ly * upZ;
        ox[i] = eyeX + offX;
        oy[i] = eyeY + offY;
        oz[i] = eyeZ + offZ;
        double toX = focus * (forwardX + sx * rightX + sy * upX) - offX; // the point in focus, from the origin
        double toY = focus * (forwardY + sx * rightY + sy * upY) - offY;
        double toZ = focus * (forwardZ + sx * rightZ + sy * upZ) - offZ;
        double inv = 1 / Math.sqrt(toX * toX + toY * toY + toZ * toZ);
        dx[i] = toX * inv;
        dy[i] = toY * inv;
        dz[i] = toZ * inv;
    }

    /** The pinhole's 1 / (A cos^3 theta), the film point shifted by the lens point o over the focus. */
    @Override
    public double directionPdf(double ox, double oy, double oz, double dx, double dy, double dz, int width,
                               int height) {
        double offX = ox - eyeX, offY = oy - eyeY, offZ = oz - eyeZ;
        double lx = offX * rightX + offY * rightY + offZ * rightZ, ly = offX * upX + offY * upY + offZ * upZ;
        return centre.throughLens(dx, dy, dz, lx, ly, focus, width, height);
    }

    @Override
    public boolean sees(double px, double py, double pz, double lensU, double lensV, int width, int height,
                        CameraSight out) {
        double a = 2 * lensU - 1, b = 2 * lensV - 1;
        double radius = aperture * discRadius(a, b), angle = discAngle(a, b);
        double lx = radius * Math.cos(angle), ly = radius * Math.sin(angle);
        return centre.seenFrom(eyeX + lx * rightX + ly * upX, eyeY + lx * rightY + ly * upY,
                eyeZ + lx * rightZ + ly * upZ, lx, ly, focus, px, py, pz, width, height, out);
    }

    /** Where the ray through the lens centre sees {@code p}: the pinhole's image point. */
    @Override
    public Optional<ImagePoint> imagePoint(Vector3d p, int width, int height) {
        return centre.imagePoint(p, width, height);
    }

    // ---------------------------------------------------------------- the concentric map of the square onto the disc

    /**
     * The radius on the unit disc of square point (a, b) in [-1, 1]^2 by the concentric map: the larger of
     * |a| and |b|, signed so that with {@link #discAngle} it lands in the square's own quarter (Shirley and
     * Chiu: squares about the centre go to circles, so strata stay compact and of equal area).
     */
    static double discRadius(double a, double b) {
        return Math.abs(a) > Math.abs(b) ? a : b;
    }

    /** The angle that goes with {@link #discRadius} of square point (a, b); 0 at the centre. */
    static double discAngle(double a, double b) {
        if (a == 0 && b == 0) {
            return 0;
        }
        return Math.abs(a) > Math.abs(b) ? Math.PI / 4 * (b / a) : Math.PI / 2 - Math.PI / 4 * (a / b);
    }
}
