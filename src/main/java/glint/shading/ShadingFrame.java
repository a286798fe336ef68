package glint.shading;

/**
 * Scratch value: an orthonormal basis (t, b, n) around a unit normal n, for sampling directions
 * in the local space where n is +z. Built without a branch on n's direction (Duff et al. 2017,
 * "Building an Orthonormal Basis, Revisited").
 */
public final class ShadingFrame {

    public double tx, ty, tz, bx, by, bz, nx, ny, nz;

    /** Sets the basis around unit normal n. */
    public void set(double nx, double ny, double nz) {
        this.nx = nx;
        this.ny = ny;
        this.nz = nz;
        double sign = Math.copySign(1.0, nz);
        double a = -1 / (sign + nz);
        double b = nx * ny * a;
        tx = 1 + sign * nx * nx * a;
        ty = sign * b;
        tz = -sign * nx;
        bx = b;
        by = sign + ny * ny * a;
        bz = -ny;
    }

    /** The local x coordinate of world vector v. */
    public double localX(double vx, double vy, double vz) {
        return vx * tx + vy * ty + vz * tz;
    }

    public double localY(double vx, double vy, double vz) {
        return vx * bx + vy * by + vz * bz;
    }

    public double localZ(double vx, double vy, double vz) {
        return vx * nx + vy * ny + vz * nz;
    }

    /** World x of local vector (x, y, z); likewise {@link #worldY}, {@link #worldZ}. */
    public double worldX(double x, double y, double z) {
        return x * tx + y * bx + z * nx;
    }

    public double worldY(double x, double y, double z) {
        return x * ty + y * by + z * ny;
    }

    public double worldZ(double x, double y, double z) {
        return x * tz + y * bz + z * nz;
    }
}
