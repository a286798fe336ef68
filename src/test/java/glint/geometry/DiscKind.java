package glint.geometry;

/**
 * A primitive kind written only for tests: flat discs (centre, unit normal, radius; 7 doubles
 * each), to show that a kind needs nothing but its bounds, intersection and surface.
 */
public final class DiscKind implements PrimitiveKind {

    private final double[] data;

    public DiscKind(double[] data) {
        this.data = data.clone();
    }

    @Override
    public int count() {
        return data.length / 7;
    }

    @Override
    public boolean bounded(int i) {
        return true;
    }

    @Override
    public void bounds(int i, double[] box, int at) {
        int k = 7 * i;
        for (int axis = 0; axis < 3; axis++) {
            double n = data[k + 3 + axis];
            double extent = data[k + 6] * Math.sqrt(Math.max(0, 1 - n * n));
            box[at + axis] = data[k + axis] - extent;
            box[at + 3 + axis] = data[k + axis] + extent;
        }
    }

    @Override
    public void boundingBall(int i, double[] ball) {
        throw new UnsupportedOperationException("a disc has no inside");
    }

    /** Whether the disc's own bounding ball overlaps the ball: true when unsure. */
    @Override
    public boolean reachesInto(int i, double cx, double cy, double cz, double r) {
        int k = 7 * i;
        double ex = data[k] - cx, ey = data[k + 1] - cy, ez = data[k + 2] - cz;
        return Math.sqrt(ex * ex + ey * ey + ez * ez) < data[k + 6] + r;
    }

    @Override
    public double intersect(int i, double ox, double oy, double oz, double dx, double dy, double dz, double tMax) {
        int k = 7 * i;
        double nx = data[k + 3], ny = data[k + 4], nz = data[k + 5];
        double t = Intersect.planeBefore(nx, ny, nz, nx * data[k] + ny * data[k + 1] + nz * data[k + 2],
                ox, oy, oz, dx, dy, dz, tMax);
        if (t == Intersect.MISS) {
            return t;
        }
        double ex = ox + t * dx - data[k], ey = oy + t * dy - data[k + 1], ez = oz + t * dz - data[k + 2];
        return ex * ex + ey * ey + ez * ez <= data[k + 6] * data[k + 6] ? t : Intersect.MISS;
    }

    @Override
    public void surfaceAt(int i, double px, double py, double pz, Hit hit) {
        int k = 7 * i;
        hit.nx = data[k + 3];
        hit.ny = data[k + 4];
        hit.nz = data[k + 5];
        double off = hit.nx * (px - data[k]) + hit.ny * (py - data[k + 1]) + hit.nz * (pz - data[k + 2]);
        hit.px = px - off * hit.nx;
        hit.py = py - off * hit.ny;
        hit.pz = pz - off * hit.nz;
    }

    @Override
    public boolean closed() {
        return false;
    }
}
