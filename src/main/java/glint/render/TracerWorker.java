package glint.render;

import glint.accel.AggregatePolicy;
import glint.accel.Candidates;
import glint.accel.Frustum;
import glint.image.FrameBuffer;

/**
 * One render thread's share of a frame: traces the pixels of the tiles it is handed, a tile row
 * at a time: the row's camera rays aimed ({@link CameraRows}; searched together when they all leave one
 * point, else one by one), each traced by the thread's
 * {@link Integrator} of the scene's light transport, and the row's pixels written. Allocates nothing per pixel.
 */
final class TracerWorker {

    private final WhittedIntegrator whitted = new WhittedIntegrator();
    private final PathIntegrator path = new PathIntegrator();
    private final BdptIntegrator bdpt = new BdptIntegrator();
    private final CameraRows rows = new CameraRows();
    /** The current row's frustum and the primitives its camera rays may meet. */
    private final Frustum rowFrustum = new Frustum();
    private final Candidates rowCandidates = new Candidates();

    /** Rays this worker has traced (camera, reflected, refracted and shadow rays). */
    long raysCast() {
        return whitted.rays() + path.rays() + bdpt.rays();
    }

    /**
     * Renders pixels [x0, x1) x [y0, y1): each pixel gets the average of samples
     * [firstSample, firstSample + sampleCount) of its {@code samples}-sample stratified pattern; light that
     * lands on other pixels goes to {@code splats}. With {@code only} (row by row), only the pixels whose entry
     * is true are traced and written, and a row without any is skipped.
     */
    void renderTile(RenderScene scene, FrameBuffer frame, Splats splats, int samples, int firstSample,
                    int sampleCount, int frameIndex, int x0, int y0, int x1, int y1, boolean[] only) {
        Integrator integrator = integrator(scene.settings.transport());
        integrator.prepare(scene);
        if (integrator == bdpt) {
            bdpt.splatInto(splats);
        }
        rows.prepare(scene.camera, frame.width(), frame.height(), x0, x1, samples, firstSample, sampleCount,
                frameIndex, only);
        int hitsLeft = scene.settings.recursionMax();
        for (int y = y0; y < y1; y++) {
            if (!rows.anyTraced(y)) {
                continue;
            }
            rows.aim(y);
            if (!rows.oneOrigin()) { // a lens: each ray searched from its own origin
                rows.trace(integrator, null, y, hitsLeft);
                rows.writeRow(frame, y);
                continue;
            }
            rows.frustum(y, rowFrustum);
            integrator.gather(rowFrustum, rowCandidates);
            boolean searchCandidates = rowCandidates.count() <= AggregatePolicy.MOST_ROW_CANDIDATES;
            if (searchCandidates) {
                rows.narrow(rowCandidates, scene.primitives);
            }
            rows.trace(integrator, searchCandidates ? rowCandidates : null, y, hitsLeft);
            rows.writeRow(frame, y);
        }
    }

    /**
     * Traces the light subpaths of chunk c of {@code vertices} for pass (frame, sample) of {@code samples} of
     * {@code scene}, for camera paths to join and merge with, and splats their light tracing.
     */
    void traceLightPaths(RenderScene scene, LightVertices vertices, int c, int frameIndex, int sample, int samples) {
        bdpt.prepare(scene);
        bdpt.traceLightPaths(vertices.chunk(c), vertices.firstPath(c), vertices.pathsIn(c), frameIndex, sample,
                samples, scene.settings.recursionMax());
    }

    /** The first pass's merge radius for a width x height image of {@code scene}. */
    double firstMergeRadius(RenderScene scene, int width, int height) {
        bdpt.prepare(scene);
        LightChoice choice = bdpt.weights.choice;
        return BdptIntegrator.firstMergeRadius(choice.pixelWidthAtCentre(width, height), choice.radius);
    }

    /**
     * The light subpaths of the bidirectional integrator's pass, from now on ({@code BdptIntegrator.pass}),
     * and the frame's splats, which their light tracing adds to.
     */
    void pass(LightVertices vertices, Splats splats) {
        bdpt.splatInto(splats);
        bdpt.pass(vertices);
    }

    private Integrator integrator(LightTransport transport) {
        return switch (transport) {
            case WHITTED -> whitted;
            case PATH -> path;
            case BDPT -> bdpt;
        };
    }
}
