package glint.render;

import glint.accel.AggregatePolicy;
import glint.accel.Candidates;
import glint.accel.Frustum;
import glint.shading.Rgb;

/**
 * One render thread's share of a frame: traces the pixels of the tiles it is handed, a tile row
 * at a time: the row's camera rays aimed ({@link CameraRows}), each traced by the thread's
 * {@link Integrator}, and the row's pixels written. Allocates nothing per pixel.
 */
final class TracerWorker {

    private final Integrator integrator = new Integrator();
    private final CameraRows rows = new CameraRows();
    /** The current row's frustum and the primitives its camera rays may meet. */
    private final Frustum rowFrustum = new Frustum();
    private final Candidates rowCandidates = new Candidates();
    // the tile and row being traced, which name each camera ray's (pixel, frame, sample)
    private int tileX0, tileFirstSample, tileSampleCount, tileFrameIndex, rowStart;

    /** Rays this worker has traced (camera, reflected, refracted and shadow rays). */
    long raysCast() {
        return integrator.rays();
    }

    /**
     * Renders pixels [x0, x1) x [y0, y1): each pixel gets the average of samples
     * [firstSample, firstSample + sampleCount) of its {@code samples}-sample stratified pattern.
     */
    void renderTile(RenderScene scene, FrameBuffer frame, int samples, int firstSample, int sampleCount,
                    int frameIndex, int x0, int y0, int x1, int y1) {
        integrator.prepare(scene);
        rows.prepare(scene.camera, frame.width(), frame.height(), x0, x1, samples, firstSample, sampleCount,
                frameIndex);
        int rays = (x1 - x0) * sampleCount;
        tileX0 = x0;
        tileFirstSample = firstSample;
        tileSampleCount = sampleCount;
        tileFrameIndex = frameIndex;
        for (int y = y0; y < y1; y++) {
            rows.aim(y);
            rowStart = y * frame.width();
            rows.frustum(y, rowFrustum);
            integrator.gather(rowFrustum, rowCandidates);
            boolean searchCandidates = rowCandidates.count() <= AggregatePolicy.MOST_ROW_CANDIDATES;
            if (searchCandidates) {
                rows.narrow(rowCandidates, scene.primitives);
            }
            traceRow(scene, rays, searchCandidates ? rowCandidates : null);
            rows.writeRow(frame, y);
        }
    }

    /**
     * Traces the row's camera rays [0, rays) from the eye into the row's radiance: first every
     * ray's nearest hit (among {@code candidates} when given, else in the aggregate), then each hit
     * shaded. Ray i is sample {@code firstSample + i % sampleCount} of pixel {@code x0 + i / sampleCount},
     * and its (pixel, frame, sample) seeds its path's random decisions.
     */
    private void traceRow(RenderScene scene, int rays, Candidates candidates) {
        CameraBasis camera = scene.camera;
        int hits = scene.settings.recursionMax();
        CameraRows r = rows;
        integrator.findCameraHits(candidates, camera.eyeX, camera.eyeY, camera.eyeZ, r.dirX, r.dirY, r.dirZ, rays,
                r.hitT, r.hitPrimitive);
        int pixel = rowStart + tileX0, sample = tileFirstSample, end = tileFirstSample + tileSampleCount;
        for (int ray = 0; ray < rays; ray++) {
            integrator.beginPath(pixel, tileFrameIndex, sample);
            Rgb radiance = integrator.shadeCamera(r.hitPrimitive[ray], r.hitT[ray], camera.eyeX, camera.eyeY,
                    camera.eyeZ, r.dirX[ray], r.dirY[ray], r.dirZ[ray], hits);
            r.radianceR[ray] = radiance.r;
            r.radianceG[ray] = radiance.g;
            r.radianceB[ray] = radiance.b;
            if (++sample == end) {
                sample = tileFirstSample;
                pixel++;
            }
        }
    }
}
