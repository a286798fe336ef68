package glint.shading;

import glint.math.Vector3d;
import java.util.List;

/**
 * A scene's lights: each light's numbers one run in a flat array, read by its kind's
 * {@link LightSampler}, which this answers through for light i.
 */
public final class Lights {

    private final int count;
    private final LightSampler[] sampler;
    /** Where light i's numbers start in {@link #data}. */
    private final int[] start;
    private final double[] data;
    private final boolean[] delta;
    /** Per light: the point all its light leaves, or null. */
    private final Vector3d[] point;
    /** The lights that rays escaping the scene may see, in order. */
    private final int[] atInfinity;

    private Lights(List<Light> lights) {
        count = lights.size();
        sampler = new LightSampler[count];
        start = new int[count];
        delta = new boolean[count];
        point = new Vector3d[count];
        int size = 0;
        for (Light light : lights) {
            size += light.data.length;
        }
        data = new double[size];
        int infinite = 0;
        for (int i = 0, at = 0; i < count; i++) {
            Light light = lights.get(i);
            sampler[i] = light.sampler;
            start[i] = at;
            System.arraycopy(light.data, 0, data, at, light.data.length);
            at += light.data.length;
            delta[i] = light.sampler.isDelta();
            point[i] = light.point;
            infinite += light.sampler.atInfinity() ? 1 : 0;
        }
        atInfinity = new int[infinite];
        for (int i = 0, k = 0; i < count; i++) {
            if (sampler[i].atInfinity()) {
                atInfinity[k++] = i;
            }
        }
    }

    /**
     * A light as the compiled scene keeps it: its kind's sampler, the numbers the sampler reads, and
     * the point all its light leaves (null where it has none; then its shadow rays may not use
     * direction cells around a point).
     */
    public record Light(LightSampler sampler, double[] data, Vector3d point) {

        public Light {
            data = data.clone();
        }
    }

    /** The lights numbered in the order given. */
    public static Lights of(List<Light> lights) {
        return new Lights(List.copyOf(lights));
    }

    public int count() {
        return count;
    }

    /** Whether light i is a delta light: no ray meets it, only its sample finds it. */
    public boolean isDelta(int i) {
        return delta[i];
    }

    /** Whether all of light i's light leaves one point, {@link #position}. */
    public boolean atPoint(int i) {
        return point[i] != null;
    }

    /** Coordinate {@code axis} (0 to 2) of the point light i's light leaves. */
    public double position(int i, int axis) {
        return axis == 0 ? point[i].x() : axis == 1 ? point[i].y() : point[i].z();
    }

    /**
     * Light i seen from point p, sampled by u1 and u2 (a delta light ignores them), into
     * {@code out} ({@link LightSampler#sample}); false where it has no direction from p.
     */
    public boolean sample(int i, double px, double py, double pz, double u1, double u2, LightSample out) {
        return sampler[i].sample(data, start[i], px, py, pz, u1, u2, out);
    }

    /** The density per solid angle with which light i's sample from p chooses unit direction w. */
    public double pdf(int i, double px, double py, double pz, double wx, double wy, double wz) {
        return sampler[i].pdf(data, start[i], px, py, pz, wx, wy, wz);
    }

    /**
     * Light leaving light i, sampled by u1 to u4, into {@code out} ({@link LightSampler#leaving}); a light
     * at infinity sends it across the disc of radius {@code sceneRadius} around c.
     */
    public void leaving(int i, double cx, double cy, double cz, double sceneRadius, double u1, double u2, double u3,
                        double u4, LightRay out) {
        sampler[i].leaving(data, start[i], cx, cy, cz, sceneRadius, u1, u2, u3, u4, out);
    }

    /**
     * The densities with which light i's {@link #leaving} chooses the ray from o along unit w, and its
     * normal at o, into {@code out} ({@link LightSampler#leavingPdf}).
     */
    public void leavingPdf(int i, double ox, double oy, double oz, double wx, double wy, double wz,
                           double sceneRadius, LightRay out) {
        sampler[i].leavingPdf(data, start[i], ox, oy, oz, wx, wy, wz, sceneRadius, out);
    }

    /** Whether light i is infinitely far ({@link LightSampler#infinitelyFar}): its rays leave a disc across the scene. */
    public boolean infinitelyFar(int i) {
        return sampler[i].infinitelyFar();
    }

    /** Light i's power, the mean of its channels ({@link LightSampler#power}). */
    public double power(int i, double sceneRadius) {
        return sampler[i].power(data, start[i], sceneRadius);
    }

    /** How many lights rays escaping the scene may see. */
    public int countAtInfinity() {
        return atInfinity.length;
    }

    /** The number of the k-th light that rays escaping the scene may see. */
    public int atInfinity(int k) {
        return atInfinity[k];
    }

    /** The radiance arriving along unit direction d from light i, at infinity, into {@code out}. */
    public void arriving(int i, double dx, double dy, double dz, Rgb out) {
        sampler[i].arriving(data, start[i], dx, dy, dz, out);
    }
}
