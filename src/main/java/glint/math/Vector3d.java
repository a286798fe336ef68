package glint.math;

/** An immutable 3-vector of doubles: points, directions and linear RGB colours of the scene model. */
public record Vector3d(double x, double y, double z) {

    public static final Vector3d ZERO = new Vector3d(0, 0, 0);
    public static final Vector3d ONE = new Vector3d(1, 1, 1);
    public static final Vector3d UNIT_X = new Vector3d(1, 0, 0);
    public static final Vector3d UNIT_Y = new Vector3d(0, 1, 0);
    public static final Vector3d UNIT_Z = new Vector3d(0, 0, 1);

    public Vector3d add(Vector3d o) {
        return new Vector3d(x + o.x, y + o.y, z + o.z);
    }

    public Vector3d sub(Vector3d o) {
        return new Vector3d(x - o.x, y - o.y, z - o.z);
    }

    public Vector3d scale(double s) {
        return new Vector3d(x * s, y * s, z * s);
    }

    public Vector3d mul(Vector3d o) {
        return new Vector3d(x * o.x, y * o.y, z * o.z);
    }

    public double dot(Vector3d o) {
        return x * o.x + y * o.y + z * o.z;
    }

    public Vector3d cross(Vector3d o) {
        return new Vector3d(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x);
    }

    public double length() {
        return Math.sqrt(dot(this));
    }

    /** This vector scaled to unit length; the zero vector has no direction and is returned unchanged. */
    public Vector3d normalize() {
        double len = length();
        return len == 0 ? this : scale(1 / len);
    }

    public double maxComponent() {
        return Math.max(x, Math.max(y, z));
    }

    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }

    @Override
    public String toString() {
        return "[" + x + ", " + y + ", " + z + "]";
    }
}
