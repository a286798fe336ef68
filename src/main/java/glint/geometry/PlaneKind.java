package glint.geometry;

/** Infinite planes n.p = offset: unit normal x, y, z and offset, 4 doubles each. */
public final class PlaneKind implements PrimitiveKind {

    private final double[] data;
    private final int count;

    /** @param data unit normal x, y, z and offset n.p of each plane (copied) */
    public PlaneKind(double[] data) {
        if (data.length % 4 != 0) {
            throw new IllegalArgumentException("4 numbers a plane, got " + data.length);
        }
        this.data = data.clone();
        this.count = data.length / 4;
    }

    @Override
    public int count() {
        return count;
    }

    @Override
    public boolean bounded(int i) {
        return false;
    }

    @Override
    public void bounds(int i, double[] box, int at) {
        for (int axis = 0; axis < 3; axis++) {
            box[at + axis] = Double.NEGATIVE_INFINITY;
            box[at + 3 + axis] = Double.POSITIVE_INFINITY;
        }
    }

    @Override
    public void boundingBall(int i, double[] ball) {
        throw new UnsupportedOperationException("a plane has no inside");
    }

    /** Whether the plane passes nearer the centre than the radius. */
    @Override
    public boolean reachesInto(int i, double cx, double cy, double cz, double r) {
        int k = 4 * i;
        double distance = Math.abs(data[k] * cx + data[k + 1] * cy + data[k + 2] * cz - data[k + 3]);
        return distance < r;
    }

    @Override
    public double intersect(int i, double ox, double oy, double oz, double dx, double dy, double dz, double tMax) {
        int k = 4 * i;
        return Intersect.planeBefore(data[k], data[k + 1], data[k + 2], data[k + 3], ox, oy, oz, dx, dy, dz, tMax);
    }

    /** The point of the plane nearest p, and its normal. */
    @Override
    public void surfaceAt(int i, double px, double py, double pz, Hit hit) {
        int k = 4 * i;
        double nx = data[k], ny = data[k + 1], nz = data[k + 2];
        double off = nx * px + ny * py + nz * pz - data[k + 3];
        hit.px = px - off * nx;
        hit.py = py - off * ny;
        hit.pz = pz - off * nz;
        hit.nx = nx;
        hit.ny = ny;
        hit.nz = nz;
    }

    @Override
    public boolean closed() {
        return false;
    }

    /** Its test is one dot product against the ball's radius. */
    @Override
    public boolean reachesIntoWithinRounding() {
        return true;
    }
}
