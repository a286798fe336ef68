package glint.render;

import glint.geometry.Hit;
import glint.shading.Rgb;

/**
 * One render thread's share of a frame: traces the pixels of the tiles it is handed, a tile row
 * at a time: the row's camera rays aimed ({@link CameraRows}), each traced by the thread's
 * {@link Integrator}, and the row's pixels written. Allocates nothing per pixel.
 */
final class TracerWorker {

    private final Integrator integrator = new Integrator();
    private final CameraRows rows = new CameraRows();

    /** Rays this worker has traced (camera, reflected, refracted and shadow rays). */
    long raysCast() {
        return integrator.rays;
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
        for (int y = y0; y < y1; y++) {
            rows.aim(y);
            traceRow(scene, y * frame.width(), x0, x1, firstSample, sampleCount, frameIndex);
            rows.writeRow(frame, y);
        }
    }

    /**
     * Traces the row's camera rays from the eye, into the row's radiance: pixels [x0, x1) of the
     * row whose first pixel has index {@code rowStart}, samples [firstSample, firstSample + sampleCount)
     * of each. Each path starts from its (pixel, frame, sample), which seeds its random decisions.
     */
    private void traceRow(RenderScene scene, int rowStart, int x0, int x1, int firstSample, int sampleCount,
                          int frameIndex) {
        CameraBasis camera = scene.camera;
        int hits = scene.settings.recursionMax();
        CameraRows r = rows;
        Integrator tracer = integrator;
        int ray = 0;
        for (int x = x0; x < x1; x++) {
            for (int sample = firstSample, end = firstSample + sampleCount; sample < end; sample++, ray++) {
                tracer.beginPath(rowStart + x, frameIndex, sample);
                Rgb radiance = tracer.trace(camera.eyeX, camera.eyeY, camera.eyeZ, r.dirX[ray], r.dirY[ray],
                        r.dirZ[ray], hits, 1, Hit.NONE, Hit.NONE);
                r.radianceR[ray] = radiance.r;
                r.radianceG[ray] = radiance.g;
                r.radianceB[ray] = radiance.b;
            }
        }
    }
}
