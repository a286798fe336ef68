package glint.render;

/**
 * What the camera rays of a frame share: they all start at the eye. Per sphere, the terms of the
 * sphere test that depend only on the eye, and the rectangle of the screen (the image plane at
 * distance 1, x right, y up) outside which no camera ray meets it. From those rectangles, the
 * spheres a tile can show, then a row of the tile, then a pixel of the row: a camera ray tests only
 * its pixel's spheres, which a sweep along the row keeps up to date (spheres enter at their left
 * edge and leave past their right edge, as in scanline rasterization). A row traced in stages
 * turns this around: each of the row's spheres is tested against the rays of the pixels its range
 * spans ({@link #leftEdge}, {@link #rightEdge}). Per worker; allocates nothing once its arrays have
 * grown to the scene.
 */
final class EyeRays {

    /** The scene (and so the camera) the per-sphere terms were computed for. */
    private RenderScene preparedFor;

    /** Per sphere, f = eye - centre (3 doubles a sphere). */
    double[] toCentre = new double[0];
    /** Per sphere, c = f.f - r^2. */
    double[] c = new double[0];
    /** Per plane, offset - n.eye. */
    double[] planeNumerator = new double[0];
    /**
     * Per sphere, its screen x range then its screen y range (4 doubles a sphere; see
     * {@link ScreenRange}); the whole line unless the sphere is wholly in front of the eye.
     */
    private double[] screenRange = new double[0];
    /** Every sphere, by the left edge of its screen range. */
    private int[] byLeftEdge = new int[0];
    private int[] sortScratch = new int[0];

    /** The spheres the current tile can show, by left edge. */
    private int[] tileSpheres = new int[0];
    private int tileCount;
    /** The spheres the current row of the tile can show, by left edge. */
    int[] rowSpheres = new int[0];
    int rowCount;
    /** The spheres the current pixel of the row can show, by left edge. */
    int[] pixelSpheres = new int[0];
    int pixelCount;
    /** The first of rowSpheres that the sweep has not reached yet. */
    private int rowNext;
    /**
     * Where the pixel's spheres next change: a pixel reaching past enterAt meets the left edge of
     * rowSpheres[rowNext]; one starting past leaveAt has left the right edge of a pixel sphere.
     */
    private double enterAt, leaveAt;

    /** Computes the per-sphere terms for this scene's camera, unless they are already computed. */
    void prepare(RenderScene s) {
        if (s == preparedFor) {
            return;
        }
        int spheres = s.sphereCount;
        if (c.length < spheres) {
            c = new double[spheres];
            toCentre = new double[3 * spheres];
            screenRange = new double[4 * spheres];
            byLeftEdge = new int[spheres];
            sortScratch = new int[spheres];
            tileSpheres = new int[spheres];
            rowSpheres = new int[spheres];
            pixelSpheres = new int[spheres];
        }
        if (planeNumerator.length < s.planeCount) {
            planeNumerator = new double[s.planeCount];
        }
        CameraBasis camera = s.camera;
        for (int i = 0; i < spheres; i++) {
            int k = 4 * i;
            double fx = camera.eyeX - s.spheres[k], fy = camera.eyeY - s.spheres[k + 1], fz = camera.eyeZ - s.spheres[k + 2];
            double r = s.spheres[k + 3];
            toCentre[3 * i] = fx;
            toCentre[3 * i + 1] = fy;
            toCentre[3 * i + 2] = fz;
            c[i] = fx * fx + fy * fy + fz * fz - r * r;
            // the centre in camera space: across (right), up and along (forward) the view
            double across = -(fx * camera.rightX + fy * camera.rightY + fz * camera.rightZ);
            double up = -(fx * camera.upX + fy * camera.upY + fz * camera.upZ);
            double along = -(fx * camera.forwardX + fy * camera.forwardY + fz * camera.forwardZ);
            ScreenRange.of(across, along, r, screenRange, k);
            ScreenRange.of(up, along, r, screenRange, k + 2);
            byLeftEdge[i] = i;
        }
        sortByLeftEdge(spheres);
        for (int i = 0; i < s.planeCount; i++) {
            int k = 4 * i;
            planeNumerator[i] = s.planes[k + 3]
                    - (s.planes[k] * camera.eyeX + s.planes[k + 1] * camera.eyeY + s.planes[k + 2] * camera.eyeZ);
        }
        tileCount = 0;
        rowCount = 0;
        pixelCount = 0;
        rowNext = 0;
        preparedFor = s;
    }

    /** The left edge of sphere i's screen x range (possibly -infinity). */
    double leftEdge(int sphere) {
        return screenRange[4 * sphere];
    }

    /** The right edge of sphere i's screen x range (possibly +infinity). */
    double rightEdge(int sphere) {
        return screenRange[4 * sphere + 1];
    }

    /** Keeps the spheres whose screen range meets the tile's rectangle [xLow, xHigh] x [yLow, yHigh]. */
    void aimTile(double xLow, double xHigh, double yLow, double yHigh) {
        int count = 0;
        for (int j = 0, n = preparedFor.sphereCount; j < n; j++) {
            int i = byLeftEdge[j];
            int k = 4 * i;
            if (screenRange[k] <= xHigh && screenRange[k + 1] >= xLow
                    && screenRange[k + 2] <= yHigh && screenRange[k + 3] >= yLow) {
                tileSpheres[count++] = i;
            }
        }
        tileCount = count;
    }

    /** Keeps of the tile's spheres those whose screen range meets the row's [yLow, yHigh]; starts the sweep. */
    void aimRow(double yLow, double yHigh) {
        int count = 0;
        for (int j = 0; j < tileCount; j++) {
            int i = tileSpheres[j];
            if (screenRange[4 * i + 2] <= yHigh && screenRange[4 * i + 3] >= yLow) {
                rowSpheres[count++] = i;
            }
        }
        rowCount = count;
        rowNext = 0;
        pixelCount = 0;
        enterAt = count > 0 ? screenRange[4 * rowSpheres[0]] : Double.POSITIVE_INFINITY;
        leaveAt = Double.POSITIVE_INFINITY;
    }

    /**
     * Moves the sweep to the pixel spanning [xLow, xHigh] of the row: pixels are visited left to
     * right (the same pixel again is fine). Keeps the left-edge order.
     */
    void aimPixel(double xLow, double xHigh) {
        if (xHigh < enterAt && xLow <= leaveAt) {
            return; // the same spheres as the last pixel
        }
        int kept = 0;
        double firstRightEdge = Double.POSITIVE_INFINITY;
        for (int j = 0; j < pixelCount; j++) {
            int i = pixelSpheres[j];
            double rightEdge = screenRange[4 * i + 1];
            if (rightEdge >= xLow) {
                pixelSpheres[kept++] = i;
                firstRightEdge = Math.min(firstRightEdge, rightEdge);
            }
        }
        while (rowNext < rowCount && screenRange[4 * rowSpheres[rowNext]] <= xHigh) {
            int i = rowSpheres[rowNext++];
            double rightEdge = screenRange[4 * i + 1];
            if (rightEdge >= xLow) {
                pixelSpheres[kept++] = i;
                firstRightEdge = Math.min(firstRightEdge, rightEdge);
            }
        }
        pixelCount = kept;
        enterAt = rowNext < rowCount ? screenRange[4 * rowSpheres[rowNext]] : Double.POSITIVE_INFINITY;
        leaveAt = firstRightEdge;
    }

    /** Sorts byLeftEdge[0, n) by the spheres' left screen edges (a stable merge sort; no allocation). */
    private void sortByLeftEdge(int n) {
        int[] from = byLeftEdge, to = sortScratch;
        for (int width = 1; width < n; width *= 2) {
            for (int lo = 0; lo < n; lo += 2 * width) {
                int mid = Math.min(lo + width, n), hi = Math.min(lo + 2 * width, n);
                int left = lo, right = mid;
                for (int out = lo; out < hi; out++) {
                    boolean takeLeft = right >= hi
                            || (left < mid && screenRange[4 * from[left]] <= screenRange[4 * from[right]]);
                    to[out] = takeLeft ? from[left++] : from[right++];
                }
            }
            int[] swap = from;
            from = to;
            to = swap;
        }
        if (from != byLeftEdge) {
            System.arraycopy(from, 0, byLeftEdge, 0, n);
        }
    }
}
