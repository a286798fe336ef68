package glint.math;

/**
 * An immutable quaternion w + xi + yj + zk. Unit quaternions orient the camera: they rotate the
 * camera's own frame (right +x, up +y, forward +z) into world space.
 */
public record Quaternion(double w, double x, double y, double z) {

    public static final Quaternion IDENTITY = new Quaternion(1, 0, 0, 0);

    /** Rotation by {@code angleRadians} about {@code axis} (need not be unit length, must not be zero). */
    public static Quaternion fromAxisAngle(Vector3d axis, double angleRadians) {
        Vector3d unit = axis.normalize();
        double half = angleRadians / 2;
        double s = Math.sin(half);
        return new Quaternion(Math.cos(half), unit.x() * s, unit.y() * s, unit.z() * s);
    }

    /**
     * The rotation by the vector's length, in radians, about its direction; the zero vector is no turn.
     * Any finite vector gives a unit quaternion, however long (its length need not be a finite double):
     * the half angle is computed from the vector scaled by its largest component.
     */
    public static Quaternion fromRotationVector(Vector3d v) {
        double largest = Math.max(Math.abs(v.x()), Math.max(Math.abs(v.y()), Math.abs(v.z())));
        if (largest == 0) {
            return IDENTITY;
        }
        Vector3d scaled = v.scale(1 / largest);
        double length = scaled.length(); // from 1 to sqrt(3)
        double half = largest / 2 * length;
        double s = Math.sin(half) / length;
        return new Quaternion(Math.cos(half), scaled.x() * s, scaled.y() * s, scaled.z() * s);
    }

    /**
     * The rotation taking the camera frame to a frame looking along {@code forward} with {@code up}
     * as near to its up axis as possible. Both must be non-zero and not parallel.
     */
    public static Quaternion lookRotation(Vector3d forward, Vector3d up) {
        Vector3d f = forward.normalize();
        Vector3d r = up.cross(f).normalize();
        Vector3d u = f.cross(r);
        return fromBasis(r, u, f);
    }

    /** The rotation whose matrix has the given orthonormal columns (Shepperd's method). */
    static Quaternion fromBasis(Vector3d c0, Vector3d c1, Vector3d c2) {
        double m00 = c0.x(), m10 = c0.y(), m20 = c0.z();
        double m01 = c1.x(), m11 = c1.y(), m21 = c1.z();
        double m02 = c2.x(), m12 = c2.y(), m22 = c2.z();
        double trace = m00 + m11 + m22;
        Quaternion q;
        if (trace > 0) {
            double s = Math.sqrt(trace + 1) * 2;
            q = new Quaternion(s / 4, (m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s);
        } else if (m00 > m11 && m00 > m22) {
            double s = Math.sqrt(1 + m00 - m11 - m22) * 2;
            q = new Quaternion((m21 - m12) / s, s / 4, (m01 + m10) / s, (m02 + m20) / s);
        } else if (m11 > m22) {
            double s = Math.sqrt(1 + m11 - m00 - m22) * 2;
            q = new Quaternion((m02 - m20) / s, (m01 + m10) / s, s / 4, (m12 + m21) / s);
        } else {
            double s = Math.sqrt(1 + m22 - m00 - m11) * 2;
            q = new Quaternion((m10 - m01) / s, (m02 + m20) / s, (m12 + m21) / s, s / 4);
        }
        return q.normalize();
    }

    /** The Hamilton product this * o: rotating by o first, then by this. */
    public Quaternion multiply(Quaternion o) {
        return new Quaternion(
                w * o.w - x * o.x - y * o.y - z * o.z,
                w * o.x + x * o.w + y * o.z - z * o.y,
                w * o.y - x * o.z + y * o.w + z * o.x,
                w * o.z + x * o.y - y * o.x + z * o.w);
    }

    public double norm() {
        return Math.sqrt(w * w + x * x + y * y + z * z);
    }

    public Quaternion normalize() {
        double n = norm();
        return new Quaternion(w / n, x / n, y / n, z / n);
    }

    /** Rotates {@code v} by this unit quaternion. */
    public Vector3d rotate(Vector3d v) {
        // t = 2 (q.xyz x v); v' = v + w t + q.xyz x t
        double tx = 2 * (y * v.z() - z * v.y());
        double ty = 2 * (z * v.x() - x * v.z());
        double tz = 2 * (x * v.y() - y * v.x());
        return new Vector3d(
                v.x() + w * tx + (y * tz - z * ty),
                v.y() + w * ty + (z * tx - x * tz),
                v.z() + w * tz + (x * ty - y * tx));
    }

    public Vector3d right() {
        return rotate(Vector3d.UNIT_X);
    }

    public Vector3d up() {
        return rotate(Vector3d.UNIT_Y);
    }

    public Vector3d forward() {
        return rotate(Vector3d.UNIT_Z);
    }
}
