package glint.render;

import glint.math.Vector3d;
import glint.scene.Camera;
import java.util.Optional;

/**
 * What makes the camera rays (world space): from a film point, an image point (px, py) in pixels from the
 * image's top-left corner, and a lens point, two numbers in [0, 1), the ray that pixel sample sees along;
 * and, the other way, the image point at which a world point is seen. Compiled from the scene's
 * {@link Camera} by {@link #of}, the one place a camera model is chosen: a {@link PinholeCamera} at
 * aperture 0, otherwise a {@link ThinLensCamera}.
 *
 * <p>A camera declares whether all its rays leave one point ({@link #oneOrigin}). Only then does the
 * renderer search a tile row's rays together ({@link CameraRows}: the row's frustum from that point, the
 * primitives searched from it once, a box narrowed to the rays between its corners' screen x), which reads
 * the pinhole's screen; a camera whose rays leave different points has each ray of a row searched in the
 * aggregate from its own origin. Implementations are immutable and shared by the render threads.
 *
 * <p>A new camera is a class of its own, chosen from the scene's camera by {@link #of}; the contract test
 * ({@code CameraModelContractTest}) holds every class {@code of} gives to this interface and fails while
 * one has no case. A tool or test renders through any model with {@link RenderScene#withCamera(CameraModel)}.
 */
public interface CameraModel {

    /** The camera model of a scene's camera: the pinhole at aperture 0 (its rays bit for bit), else a thin lens. */
    static CameraModel of(Camera camera) {
        return camera.aperture() > 0 ? new ThinLensCamera(camera) : new PinholeCamera(camera);
    }

    /**
     * Whether every ray leaves the same point, {@link #eye()}: true only of a {@link PinholeCamera}, whose
     * screen the row search reads; any other camera answers false and its rows are searched ray by ray.
     */
    boolean oneOrigin();

    /** The camera's centre: the point every ray of a pinhole leaves, the centre of a lens. */
    Vector3d eye();

    /**
     * Stores the camera ray of a width x height image through film point (px, py) (pixels from the top-left)
     * and lens point (lensU, lensV) in [0, 1)^2: its origin into (ox[i], oy[i], oz[i]) and its unit direction
     * into (dx[i], dy[i], dz[i]). Allocates nothing.
     */
    void ray(double px, double py, double lensU, double lensV, int width, int height, double[] ox, double[] oy,
             double[] oz, double[] dx, double[] dy, double[] dz, int i);

    /**
     * The density per solid angle of the camera ray from o along unit d, its film point uniform over a
     * width x height image (and its lens point chosen as it is): 1 / (A cos^3 theta), with A the area of the
     * screen one unit ahead and theta the angle between d and the view direction; 0 for a ray no film
     * point of the image makes. It is also the camera's importance along the ray: a point whose radiance
     * L reaches the camera along it adds L times it, per light path, to the pixel it is seen at
     * ({@code BdptIntegrator}). A camera that does not answer (0) is never reached from a light.
     */
    default double directionPdf(double ox, double oy, double oz, double dx, double dy, double dz, int width,
                                int height) {
        return 0;
    }

    /**
     * The camera seen from world point p, for a path started at a light: a point of the lens chosen by
     * (lensU, lensV) as {@link #ray} chooses it (the eye, for a pinhole), the film point of a width x height
     * image whose ray from that lens point meets p, and the importance along that ray, into {@code out}.
     * False where no camera ray meets p (on or behind the lens's plane, outside the image), and for a
     * camera that does not answer. Allocates nothing.
     */
    default boolean sees(double px, double py, double pz, double lensU, double lensV, int width, int height,
                         CameraSight out) {
        return false;
    }

    /**
     * The image point (px, py) of a width x height image at which world point {@code p} is seen: through
     * the eye, or a lens's centre, whose ray through that point meets {@code p}. Empty for a point on or
     * behind the camera's plane (facing the way it looks); a point outside the field of view has a point
     * outside [0, width] x [0, height]. Allocates: for tests and tools, not the per-pixel path.
     */
    Optional<ImagePoint> imagePoint(Vector3d p, int width, int height);

    /**
     * A point of an image in pixels from its top-left corner, {@code px} to the right and {@code py} down;
     * it lies in pixel ({@link #column()}, {@link #row()}).
     */
    record ImagePoint(double px, double py) {

        /** The column of the pixel the point lies in. */
        public int column() {
            return (int) Math.floor(px);
        }

        /** The row of the pixel the point lies in. */
        public int row() {
            return (int) Math.floor(py);
        }
    }
}
