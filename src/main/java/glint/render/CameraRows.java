package glint.render;

/**
 * The camera rays of one tile row, per worker: their unit directions (world space), aimed for the
 * whole row before any is traced so that the square roots and divisions of many rays overlap, and
 * the radiance each ray brings back, averaged into the row's pixels once it is traced. Ray i of a
 * row is sample {@code i % sampleCount} of pixel {@code x0 + i / sampleCount}. The arrays grow,
 * never shrink, so a frame allocates nothing once the widest tile has been seen.
 */
final class CameraRows {

    // per frame: screen x = px * scaleX + offsetX, likewise y (image plane at distance 1, y up)
    private double scaleX, offsetX, scaleY, offsetY;

    // one coordinate an array, so that a packet of neighbouring rays loads with one instruction
    double[] dirX = new double[0], dirY = new double[0], dirZ = new double[0];
    double[] radianceR = new double[0], radianceG = new double[0], radianceB = new double[0];
    /** Screen x of the centres of pixels [centresFor, centresFor + centreCount), shared by the tile's rows. */
    private double[] centreX = new double[0];
    private int centresFor, centreCount;

    /** Sets the mapping from pixels to screen for a frame of this size and room for {@code rays} rays a row. */
    void prepare(CameraBasis camera, int width, int height, int rays) {
        double halfWidth = camera.tanHalfFov;
        double halfHeight = halfWidth * height / width;
        scaleX = 2 * halfWidth / width;
        offsetX = -halfWidth;
        scaleY = -2 * halfHeight / height;
        offsetY = halfHeight;
        centreCount = 0; // the mapping may have changed
        if (dirX.length < rays) {
            centreX = new double[rays];
            dirX = new double[rays];
            dirY = new double[rays];
            dirZ = new double[rays];
            radianceR = new double[rays];
            radianceG = new double[rays];
            radianceB = new double[rays];
        }
    }

    /** Screen x of image x (pixels from the left). */
    double screenX(double px) {
        return px * scaleX + offsetX;
    }

    /** Image x (pixels from the left, fractional) of screen x: the inverse of {@link #screenX}. */
    double pixelOf(double sx) {
        return (sx - offsetX) / scaleX;
    }

    /** Screen y of image y (pixels from the top; screen y grows upwards). */
    double screenY(double py) {
        return py * scaleY + offsetY;
    }

    /**
     * Aims the camera rays of pixels [x0, x1) of row y: each pixel's samples [firstSample,
     * firstSample + sampleCount) of its side x side stratified pattern, or its centre when side is 1.
     */
    void aim(CameraBasis camera, int width, int y, int x0, int x1, int side, int firstSample, int sampleCount,
             int frameIndex) {
        if (side == 1) {
            aimCentres(camera, y, x0, x1);
            return;
        }
        int ray = 0;
        for (int x = x0; x < x1; x++) {
            int pixelIndex = y * width + x;
            for (int sample = firstSample, end = firstSample + sampleCount; sample < end; sample++) {
                int cellX = sample % side, cellY = sample / side;
                long h = SamplePattern.hash(pixelIndex, frameIndex, sample);
                aim(camera, ray++, x + (cellX + SamplePattern.jitterU(h)) / side,
                        y + (cellY + SamplePattern.jitterV(h)) / side);
            }
        }
    }

    /**
     * Aims the camera rays through the centres of pixels [x0, x1) of row y, ray i through pixel
     * x0 + i: the arithmetic of {@link #aim(CameraBasis, int, double, double)}, in a loop without
     * branches or calls, which the JIT turns into SIMD instructions (four rays an instruction
     * where the processor has AVX2).
     */
    private void aimCentres(CameraBasis camera, int y, int x0, int x1) {
        double sy = screenY(y + 0.5);
        double upX = sy * camera.upX, upY = sy * camera.upY, upZ = sy * camera.upZ;
        double forwardX = camera.forwardX, forwardY = camera.forwardY, forwardZ = camera.forwardZ;
        double rightX = camera.rightX, rightY = camera.rightY, rightZ = camera.rightZ;
        int n = x1 - x0;
        if (centresFor != x0 || centreCount != n) {
            for (int ray = 0; ray < n; ray++) {
                centreX[ray] = screenX(x0 + ray + 0.5);
            }
            centresFor = x0;
            centreCount = n;
        }
        double[] outX = dirX, outY = dirY, outZ = dirZ, screenX = centreX;
        for (int ray = 0; ray < n; ray++) {
            double sx = screenX[ray];
            double dx = forwardX + sx * rightX + upX;
            double dy = forwardY + sx * rightY + upY;
            double dz = forwardZ + sx * rightZ + upZ;
            double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
            outX[ray] = dx * inv;
            outY[ray] = dy * inv;
            outZ[ray] = dz * inv;
        }
    }

    /** Stores the unit direction of the camera ray through image point (px, py), in pixels from the top-left. */
    void aim(CameraBasis camera, int ray, double px, double py) {
        double sx = screenX(px), sy = screenY(py);
        double dx = camera.forwardX + sx * camera.rightX + sy * camera.upX;
        double dy = camera.forwardY + sx * camera.rightY + sy * camera.upY;
        double dz = camera.forwardZ + sx * camera.rightZ + sy * camera.upZ;
        double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
        dirX[ray] = dx * inv;
        dirY[ray] = dy * inv;
        dirZ[ray] = dz * inv;
    }

    /** Writes into the frame the average of each pixel's traced samples, pixels [x0, x1) of row y. */
    void writeRow(FrameBuffer frame, int y, int x0, int x1, int sampleCount) {
        if (sampleCount == 1) {
            for (int x = x0, ray = 0; x < x1; x++, ray++) {
                frame.set(x, y, radianceR[ray], radianceG[ray], radianceB[ray]);
            }
            return;
        }
        double inv = 1.0 / sampleCount;
        int ray = 0;
        for (int x = x0; x < x1; x++) {
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
