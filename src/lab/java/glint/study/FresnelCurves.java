package glint.study;

import glint.shading.Optics;

/**
 * Reflectance of a smooth dielectric (ior 1.5 in air) against the angle of incidence, from outside
 * and from inside the glass: the exact Fresnel equations, Schlick's approximation used as Glint uses
 * it ({@link Optics#schlickDielectric}: the cosine on the air side, 1 past the critical angle), and
 * the textbook slip of feeding Schlick the incident cosine inside the glass.
 */
public final class FresnelCurves {

    public static final double IOR = 1.5;

    private FresnelCurves() {
    }

    /** Schlick's F0 for the boundary: ((n - 1) / (n + 1))^2 = 0.04 for n = 1.5. */
    public static double f0() {
        double r = (IOR - 1) / (IOR + 1);
        return r * r;
    }

    /** The critical angle inside the glass, degrees: asin(1 / n) = 41.81 for n = 1.5. */
    public static double criticalAngleDegrees() {
        return Math.toDegrees(Math.asin(1 / IOR));
    }

    public static double exactOutside(double degrees) {
        return Optics.fresnelDielectric(cos(degrees), 1 / IOR);
    }

    public static double schlickOutside(double degrees) {
        return Optics.schlickDielectric(cos(degrees), 1 / IOR);
    }

    public static double exactInside(double degrees) {
        return Optics.fresnelDielectric(cos(degrees), IOR);
    }

    public static double schlickInside(double degrees) {
        return Optics.schlickDielectric(cos(degrees), IOR);
    }

    /** Schlick with the incident (glass-side) cosine and no total internal reflection: the textbook slip. */
    public static double schlickWrongCosineInside(double degrees) {
        return Optics.schlick(f0(), cos(degrees));
    }

    /** Angles 0, step, ..., 90 degrees. */
    public static double[] angles(double step) {
        int n = (int) Math.round(90 / step) + 1;
        double[] a = new double[n];
        for (int i = 0; i < n; i++) {
            a[i] = Math.min(90, i * step);
        }
        return a;
    }

    private static double cos(double degrees) {
        return degrees >= 90 ? 0 : Math.cos(Math.toRadians(degrees));
    }
}
