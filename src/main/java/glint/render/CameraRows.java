package glint.render;

import glint.accel.Candidates;
import glint.accel.Frustum;
import glint.geometry.Primitives;
import glint.image.FrameBuffer;
import glint.shading.Rgb;
import java.util.Arrays;

/**
 * The camera rays of one tile row, per worker: their unit directions (world space), made by the
 * scene's {@link CameraModel} for the whole row before any is traced so that the square roots and
 * divisions of many rays overlap, and the radiance each ray brings back, averaged into the row's
 * pixels once it is traced. Ray i of a row is sample {@code i % sampleCount} of pixel
 * {@code x0 + i / sampleCount}. The arrays grow, never shrink, so a frame allocates nothing once the
 * widest tile has been seen. The row's search (its {@link #frustum}, {@link #narrow} and the hits of
 * {@link #trace} among candidates) relies on what a camera of {@link #oneOrigin()} promises: every ray
 * leaves its eye, through the pinhole's screen. A camera with a lens has each ray's own origin (from
 * its lens sample, {@link PathSamples#LENS}), and its rows' rays are searched one by one.
 */
final class CameraRows {

    // per frame: the camera's screen per pixel and screen at the image's left and top edges
    private double scaleX, offsetX, scaleY, offsetY;

    // the tile being traced: its camera (the pinhole, when every ray leaves its eye, else null), image
    // width and height, pixel columns [x0, x1), and the samples [firstSample, firstSample + sampleCount)
    // of each pixel's side x side pattern for frame frameIndex
    private CameraModel camera;
    private PinholeCamera pinhole;
    private int width, height, x0, x1, side, firstSample, sampleCount, frameIndex;
    /** The pixels traced, row by row, or null for all (adaptive sampling). */
    private boolean[] only;

    /** The row's ray directions, one coordinate an array; written only here, read by tests. */
    double[] dirX = new double[0], dirY = new double[0], dirZ = new double[0];
    /** The row's ray origins: each ray's own through a lens, the eye for every ray of a pinhole. */
    double[] originX = new double[0], originY = new double[0], originZ = new double[0];
    /** The lens sample of a ray: its two numbers, stratified over the pixel's samples. */
    private final PathSamples lens = new PathSamples();
    private double[] radianceR = new double[0], radianceG = new double[0], radianceB = new double[0];
    /** Each ray's nearest hit, found for the whole row before any is shaded: distance and primitive. */
    private double[] hitT = new double[0];
    private int[] hitPrimitive = new int[0];
    /** Screen x of the centres of the tile's pixels, shared by its rows (with one sample a pixel). */
    private double[] centreX = new double[0];

    /**
     * Sets the mapping from pixels to screen for a frame of this size, and the tile: pixel columns
     * [x0, x1), each pixel's samples [firstSample, firstSample + sampleCount) of its
     * {@code samples}-sample stratified pattern for frame {@code frameIndex}.
     */
    void prepare(CameraModel camera, int width, int height, int x0, int x1, int samples, int firstSample,
                 int sampleCount, int frameIndex) {
        prepare(camera, width, height, x0, x1, samples, firstSample, sampleCount, frameIndex, null);
    }

    /** {@link #prepare}, tracing only the pixels whose entry of {@code only} (row by row) is true; null: all. */
    void prepare(CameraModel camera, int width, int height, int x0, int x1, int samples, int firstSample,
                 int sampleCount, int frameIndex, boolean[] only) {
        this.only = only;
        this.camera = camera;
        this.pinhole = camera.oneOrigin() && camera instanceof PinholeCamera p ? p : null;
        if (pinhole != null) {
            scaleX = pinhole.screenPerPixelX(width);
            offsetX = pinhole.screenLeft();
            scaleY = pinhole.screenPerPixelY(width, height);
            offsetY = pinhole.screenTop(width, height);
        }
        this.width = width;
        this.height = height;
        this.x0 = x0;
        this.x1 = x1;
        this.side = (int) Math.round(Math.sqrt(samples));
        this.firstSample = firstSample;
        this.sampleCount = sampleCount;
        this.frameIndex = frameIndex;
        int rays = (x1 - x0) * sampleCount;
        if (dirX.length < rays) {
            centreX = new double[rays];
            dirX = new double[rays];
            dirY = new double[rays];
            dirZ = new double[rays];
            originX = new double[rays];
            originY = new double[rays];
            originZ = new double[rays];
            radianceR = new double[rays];
            radianceG = new double[rays];
            radianceB = new double[rays];
            hitT = new double[rays];
            hitPrimitive = new int[rays];
        }
        if (pinhole != null) { // every ray leaves the eye
            Arrays.fill(originX, 0, rays, pinhole.eyeX());
            Arrays.fill(originY, 0, rays, pinhole.eyeY());
            Arrays.fill(originZ, 0, rays, pinhole.eyeZ());
            for (int ray = 0, n = x1 - x0; ray < n; ray++) {
                centreX[ray] = screenX(x0 + ray + 0.5);
            }
        }
    }

    /** Whether any pixel of the tile's row y is traced. */
    boolean anyTraced(int y) {
        if (only == null) {
            return true;
        }
        for (int p = y * width + x0, end = y * width + x1; p < end; p++) {
            if (only[p]) {
                return true;
            }
        }
        return false;
    }

    /** How far past its pixels' edges a row's frustum reaches, in pixels: far more than any rounding of a ray's direction. */
    private static final double FRUSTUM_MARGIN = 0.01;

    private final double[] edges = new double[12];

    /**
     * Sets {@code out} to the frustum that holds every camera ray of the tile's row y: from the
     * eye through the row's pixels, widened by {@link #FRUSTUM_MARGIN} all round.
     */
    void frustum(int y, Frustum out) {
        double left = screenX(x0 - FRUSTUM_MARGIN), right = screenX(x1 + FRUSTUM_MARGIN);
        double top = screenY(y - FRUSTUM_MARGIN), bottom = screenY(y + 1 + FRUSTUM_MARGIN);
        PinholeCamera c = pinhole;
        c.through(left, top, edges, 0);
        c.through(right, top, edges, 3);
        c.through(right, bottom, edges, 6);
        c.through(left, bottom, edges, 9);
        out.set(c.eyeX(), c.eyeY(), c.eyeZ(), edges);
    }

    private final double[] box = new double[6];

    /**
     * Narrows each bounded primitive of a row's {@code candidates} to the row's rays that can meet
     * it. A ray from the eye meets a box wholly in front of the eye only where its screen x lies
     * between the screen x of the box's corners (the box is convex, and screen x is v.right / v.forward
     * of a point v from the eye), so only the rays of the pixels over that span, and one more pixel on
     * each side, are searched for it. A box reaching behind the eye keeps every ray. The same for
     * every row of the tile, as screen x does not depend on the row.
     */
    void narrow(Candidates candidates, Primitives primitives) {
        PinholeCamera c = pinhole;
        double eyeX = c.eyeX(), eyeY = c.eyeY(), eyeZ = c.eyeZ();
        double forwardX = c.forwardX(), forwardY = c.forwardY(), forwardZ = c.forwardZ();
        double rightX = c.rightX(), rightY = c.rightY(), rightZ = c.rightZ();
        for (int i = 0; i < candidates.count(); i++) {
            int p = candidates.primitive(i);
            if (!primitives.bounded(p)) {
                continue;
            }
            primitives.bounds(p, box, 0);
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            boolean inFront = true;
            for (int corner = 0; corner < 8 && inFront; corner++) {
                double vx = box[(corner & 1) * 3] - eyeX;
                double vy = box[1 + (corner >> 1 & 1) * 3] - eyeY;
                double vz = box[2 + (corner >> 2) * 3] - eyeZ;
                double depth = vx * forwardX + vy * forwardY + vz * forwardZ;
                inFront = depth > 0;
                double sx = (vx * rightX + vy * rightY + vz * rightZ) / depth;
                lo = Math.min(lo, sx);
                hi = Math.max(hi, sx);
            }
            if (inFront) {
                double left = Math.floor((lo - offsetX) / scaleX) - 1, right = Math.floor((hi - offsetX) / scaleX) + 2;
                int firstPixel = (int) Math.max(x0, Math.min(x1, left));
                int endPixel = (int) Math.max(x0, Math.min(x1, right));
                candidates.narrow(i, (firstPixel - x0) * sampleCount, (endPixel - x0) * sampleCount);
            }
        }
    }

    /** Screen x of image x (pixels from the left). */
    double screenX(double px) {
        return PinholeCamera.screen(px, scaleX, offsetX);
    }

    /** Screen y of image y (pixels from the top; screen y grows upwards). */
    double screenY(double py) {
        return PinholeCamera.screen(py, scaleY, offsetY);
    }

    /** Whether every ray of the tile leaves one point, the camera's eye: the row search applies. */
    boolean oneOrigin() {
        return pinhole != null;
    }

    /**
     * Aims the camera rays of the tile's row y: each pixel's samples of its stratified pattern, or,
     * when the pattern has one sample, its centre. A pinhole's centres are aimed along the row as single
     * points are ({@link PinholeCamera#aimRow}), from the tile's screen x of each pixel centre worked out
     * once. A camera with a lens gives each ray its origin too, from the sample's lens point, the pair
     * {@link PathSamples#LENS} of (pixel, frame, sample): one in each cell of the pixel's side x side
     * grid, shuffled apart from the film's cells.
     */
    void aim(int y) {
        if (pinhole != null && side == 1) {
            pinhole.aimRow(centreX, x1 - x0, screenY(y + 0.5), dirX, dirY, dirZ);
            return;
        }
        int ray = 0, samples = side * side;
        for (int x = x0; x < x1; x++) {
            int pixelIndex = y * width + x;
            for (int sample = firstSample, end = firstSample + sampleCount; sample < end; sample++) {
                double px = x + 0.5, py = y + 0.5;
                if (side > 1) {
                    long h = SamplePattern.hash(pixelIndex, frameIndex, sample);
                    px = x + (sample % side + SamplePattern.jitterU(h)) / side;
                    py = y + (sample / side + SamplePattern.jitterV(h)) / side;
                }
                if (pinhole != null) {
                    aimThrough(ray++, px, py);
                } else {
                    lens.begin(pixelIndex, frameIndex, sample, samples);
                    lens.pair(PathSamples.LENS);
                    camera.ray(px, py, lens.u1, lens.u2, width, height, originX, originY, originZ, dirX, dirY,
                            dirZ, ray++);
                }
            }
        }
    }

    /** Stores the unit direction of camera ray i through image point (px, py), in pixels from the top-left. */
    void aimThrough(int ray, double px, double py) {
        pinhole.aim(screenX(px), screenY(py), dirX, dirY, dirZ, ray);
    }

    /**
     * Traces the aimed camera rays of row y into their radiance: first every ray's nearest hit
     * (a pinhole's among {@code candidates} when given, else in the aggregate; a lens's ray by ray from
     * its own origin), then each hit shaded with {@code hitsLeft} hits. Ray i is sample
     * {@code firstSample + i % sampleCount} of pixel {@code x0 + i / sampleCount}, and its (pixel, frame,
     * sample) seeds its path's random decisions.
     */
    void trace(Integrator integrator, Candidates candidates, int y, int hitsLeft) {
        int rays = (x1 - x0) * sampleCount;
        if (pinhole != null) {
            integrator.findCameraHits(candidates, pinhole.eyeX(), pinhole.eyeY(), pinhole.eyeZ(), dirX, dirY, dirZ,
                    rays, hitT, hitPrimitive);
        } else {
            integrator.findCameraHits(originX, originY, originZ, dirX, dirY, dirZ, rays, hitT, hitPrimitive);
        }
        int pixel = y * width + x0, sample = firstSample, end = firstSample + sampleCount;
        boolean[] traced = only;
        for (int ray = 0; ray < rays; ray++) {
            if (traced != null && !traced[pixel]) { // converged: no path starts here
                radianceR[ray] = 0;
                radianceG[ray] = 0;
                radianceB[ray] = 0;
                if (++sample == end) {
                    sample = firstSample;
                    pixel++;
                }
                continue;
            }
            integrator.beginPath(pixel, frameIndex, sample, side * side);
            Rgb radiance = integrator.shadeCamera(hitPrimitive[ray], hitT[ray], originX[ray], originY[ray],
                    originZ[ray], dirX[ray], dirY[ray], dirZ[ray], hitsLeft);
            radianceR[ray] = radiance.r;
            radianceG[ray] = radiance.g;
            radianceB[ray] = radiance.b;
            if (++sample == end) {
                sample = firstSample;
                pixel++;
            }
        }
    }

    /** Writes into the frame the average of each pixel's traced samples, the tile's pixels of row y that are traced. */
    void writeRow(FrameBuffer frame, int y) {
        boolean[] traced = only;
        if (sampleCount == 1) {
            for (int x = x0, ray = 0; x < x1; x++, ray++) {
                if (traced == null || traced[y * width + x]) {
                    frame.set(x, y, radianceR[ray], radianceG[ray], radianceB[ray]);
                }
            }
            return;
        }
        double inv = 1.0 / sampleCount;
        int ray = 0;
        for (int x = x0; x < x1; x++) {
            if (traced != null && !traced[y * width + x]) {
                ray += sampleCount;
                continue;
            }
            double sumR = 0, sumG = 0, sumB = 0;
            for (int end = ray + sampleCount; ray < end; ray++) {
                sumR += radianceR[ray];
                sumG += radianceG[ray];
                sumB += radianceB[ray];
            }
            frame.set(x, y, sumR * inv, sumG * inv, sumB * inv);
        }
    }
}
