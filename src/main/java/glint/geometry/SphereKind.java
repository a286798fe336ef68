package glint.geometry;

/** SphereKind: centre x, y, z and radius, 4 doubles each. */
public final class SphereKind implements PrimitiveKind {

    private final double[] data;
    private final int count;
    /** 1 / radius of each sphere. */
    private final double[] inverseRadii;

    /** @param data centre x, y, z and radius of each sphere (copied) */
    public SphereKind(double[] data) {
        if (data.length % 4 != 0) {
            throw new IllegalArgumentException("4 numbers a sphere, got " + data.length);
        }
        this.data = data.clone();
        this.count = data.length / 4;
        this.inverseRadii = new double[count];
        for (int i = 0; i < count; i++) {
            inverseRadii[i] = 1 / data[4 * i + 3];
        }
    }

    @Override
    public int count() {
        return count;
    }

    @Override
    public boolean bounded(int i) {
        return true;
    }

    /** The box, a rounding step wider on each side than centre -+ radius, so that it holds the whole sphere. */
    @Override
    public void bounds(int i, double[] box, int at) {
        int k = 4 * i;
        double r = data[k + 3];
        for (int axis = 0; axis < 3; axis++) {
            box[at + axis] = Math.nextDown(data[k + axis] - r);
            box[at + 3 + axis] = Math.nextUp(data[k + axis] + r);
        }
    }

    @Override
    public void boundingBall(int i, double[] ball) {
        System.arraycopy(data, 4 * i, ball, 0, 4);
    }

    /** Whether the two balls overlap. */
    @Override
    public boolean reachesInto(int i, double cx, double cy, double cz, double r) {
        int k = 4 * i;
        double ex = data[k] - cx, ey = data[k + 1] - cy, ez = data[k + 2] - cz;
        double distance = Math.sqrt(ex * ex + ey * ey + ez * ez);
        return distance < data[k + 3] + r;
    }

    @Override
    public double intersect(int i, double ox, double oy, double oz, double dx, double dy, double dz, double tMax) {
        int k = 4 * i;
        return Intersect.sphereBefore(data[k], data[k + 1], data[k + 2], data[k + 3], ox, oy, oz, dx, dy, dz, tMax);
    }

    /** The origin's offset from the centre and its square less r^2, once for all the rays. */
    @Override
    public void nearestFromOrigin(int i, int number, double ox, double oy, double oz, double[] dx, double[] dy,
                                  double[] dz, int first, int end, double[] nearestT, int[] nearestPrimitive) {
        int k = 4 * i;
        double radius = data[k + 3];
        double fx = ox - data[k], fy = oy - data[k + 1], fz = oz - data[k + 2];
        double c = fx * fx + fy * fy + fz * fz - radius * radius;
        for (int r = first; r < end; r++) {
            double t = Intersect.sphereFrom(fx, fy, fz, c, radius, dx[r], dy[r], dz[r], nearestT[r]);
            if (t < nearestT[r]) {
                nearestT[r] = t;
                nearestPrimitive[r] = number;
            }
        }
    }

    /** The point of the sphere nearest p (removes the error t carries into p) and the outward normal. */
    @Override
    public void surfaceAt(int i, double px, double py, double pz, Hit hit) {
        int k = 4 * i;
        double cx = data[k], cy = data[k + 1], cz = data[k + 2], radius = data[k + 3];
        double ex = px - cx, ey = py - cy, ez = pz - cz;
        double inv = 1 / Math.sqrt(ex * ex + ey * ey + ez * ez);
        hit.nx = ex * inv;
        hit.ny = ey * inv;
        hit.nz = ez * inv;
        hit.px = cx + radius * hit.nx;
        hit.py = cy + radius * hit.ny;
        hit.pz = cz + radius * hit.nz;
    }

    /**
     * A chord of a sphere is 2 r cos long and meets the sphere at its far end at the same angle as
     * at its near end, so every bounce inside it meets the surface at the same cosine.
     */
    @Override
    public double chordInside(int i, double px, double py, double pz, double ux, double uy, double uz,
                              double cosInside, double offset, Hit end) {
        int k = 4 * i;
        double radius = data[k + 3];
        if (!(radius > offset)) {
            return Double.NaN;
        }
        double chord = 2 * radius * cosInside;
        double qx = px + chord * ux, qy = py + chord * uy, qz = pz + chord * uz;
        double inverseRadius = inverseRadii[i];
        end.t = chord;
        end.px = qx;
        end.py = qy;
        end.pz = qz;
        end.nx = (qx - data[k]) * inverseRadius;
        end.ny = (qy - data[k + 1]) * inverseRadius;
        end.nz = (qz - data[k + 2]) * inverseRadius;
        return cosInside;
    }

    @Override
    public boolean closed() {
        return true;
    }
}
