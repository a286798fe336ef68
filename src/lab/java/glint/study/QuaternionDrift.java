package glint.study;

import glint.math.Quaternion;
import glint.math.Vector3d;

/**
 * The camera turned a million times the way a window turns it: each step a small yaw about the world
 * up (applied on the left) and a small pitch about the camera's own right axis (applied on the
 * right), with step angles that never repeat a pattern. Records how far |q| strays from 1, with and
 * without re-normalising after every step, in double (Glint's {@link Quaternion}) and, for
 * comparison, in float (the same formulas with every operation rounded to float).
 */
public final class QuaternionDrift {

    private QuaternionDrift() {
    }

    /** |q| - 1 after each step count in {@code checkpoints} (ascending). */
    public static double[] normError(long[] checkpoints, Precision precision, boolean renormalize) {
        double[] out = new double[checkpoints.length];
        Quaternion start = Quaternion.lookRotation(new Vector3d(0.3, -0.2, 1), Vector3d.UNIT_Y);
        double[] q = {r(precision, start.w()), r(precision, start.x()), r(precision, start.y()), r(precision, start.z())};
        int next = 0;
        long last = checkpoints[checkpoints.length - 1];
        for (long step = 1; step <= last; step++) {
            double yaw = 0.011 * Math.sin(step * 0.61803398875);
            double pitch = 0.007 * Math.cos(step * 0.41421356237);
            if (precision == Precision.DOUBLE) {
                Quaternion g = new Quaternion(q[0], q[1], q[2], q[3]);
                g = Quaternion.fromAxisAngle(Vector3d.UNIT_Y, yaw).multiply(g)
                        .multiply(Quaternion.fromAxisAngle(Vector3d.UNIT_X, pitch));
                if (renormalize) {
                    g = g.normalize();
                }
                q = new double[] {g.w(), g.x(), g.y(), g.z()};
            } else {
                q = multiplyFloat(multiplyFloat(axisAngleFloat(1, yaw), q), axisAngleFloat(0, pitch));
                if (renormalize) {
                    double n = normFloat(q);
                    for (int i = 0; i < 4; i++) {
                        q[i] = (float) (q[i] / n);
                    }
                }
            }
            while (next < checkpoints.length && checkpoints[next] == step) {
                out[next++] = precision == Precision.DOUBLE
                        ? new Quaternion(q[0], q[1], q[2], q[3]).norm() - 1 : normFloat(q) - 1;
            }
        }
        return out;
    }

    /** 1, 2, 5, 10, 20, 50, ... up to {@code max}. */
    public static long[] checkpoints(long max) {
        java.util.List<Long> list = new java.util.ArrayList<>();
        for (long decade = 1; decade <= max; decade *= 10) {
            for (long m : new long[] {1, 2, 5}) {
                if (decade * m <= max) {
                    list.add(decade * m);
                }
            }
        }
        return list.stream().mapToLong(Long::longValue).toArray();
    }

    private static double r(Precision p, double v) {
        return p.round(v);
    }

    /** Rotation about axis 0 (x) or 1 (y) by the angle, in float. */
    private static double[] axisAngleFloat(int axis, double angle) {
        float half = (float) (angle / 2);
        float s = (float) Math.sin(half), c = (float) Math.cos(half);
        return axis == 0 ? new double[] {c, s, 0, 0} : new double[] {c, 0, s, 0};
    }

    /** The Hamilton product a * b with every operation rounded to float (Glint's formula and order). */
    private static double[] multiplyFloat(double[] a, double[] b) {
        float aw = (float) a[0], ax = (float) a[1], ay = (float) a[2], az = (float) a[3];
        float bw = (float) b[0], bx = (float) b[1], by = (float) b[2], bz = (float) b[3];
        return new double[] {
            aw * bw - ax * bx - ay * by - az * bz,
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw};
    }

    private static double normFloat(double[] q) {
        float w = (float) q[0], x = (float) q[1], y = (float) q[2], z = (float) q[3];
        return (float) Math.sqrt(w * w + x * x + y * y + z * z);
    }
}
