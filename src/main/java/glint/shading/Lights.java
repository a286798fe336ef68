package glint.shading;

import glint.math.Vector3d;
import java.util.List;

/** A scene's lights in flat arrays, each sampled by its type's {@link LightSampler}. */
public final class Lights {

    private final int count;
    private final LightSampler[] sampler;
    private final boolean[] atPoint;
    /** Per light: what its sampler reads, e.g. a point light's position or the unit direction towards a directional one. */
    private final double[] vector;
    /** Per light: colour x intensity. */
    private final double[] power;

    private Lights(List<Light> lights) {
        count = lights.size();
        sampler = new LightSampler[count];
        atPoint = new boolean[count];
        vector = new double[3 * count];
        power = new double[3 * count];
        for (int i = 0; i < count; i++) {
            Light light = lights.get(i);
            sampler[i] = light.sampler;
            atPoint[i] = light.atPoint;
            put(vector, i, light.vector);
            put(power, i, light.power);
        }
    }

    /**
     * A light as the compiled scene keeps it: its type's sampler, whether all its light leaves one
     * point (then {@code vector} is that point), the vector the sampler reads and its power.
     */
    public record Light(LightSampler sampler, boolean atPoint, Vector3d vector, Vector3d power) {
    }

    /** The lights numbered in the order given. */
    public static Lights of(List<Light> lights) {
        return new Lights(List.copyOf(lights));
    }

    public int count() {
        return count;
    }

    /** Whether all of light i's light leaves one point, {@link #position}. */
    public boolean atPoint(int i) {
        return atPoint[i];
    }

    /** Coordinate {@code axis} (0 to 2) of the point light i's light leaves. */
    public double position(int i, int axis) {
        return vector[3 * i + axis];
    }

    /**
     * Light i seen from surface point p of unit normal n, into {@code out}; returns n.l, the cosine
     * at the surface, or 0 (leaving {@code out} alone) where it has no direction from p.
     */
    public double sample(int i, double px, double py, double pz, double nx, double ny, double nz, LightSample out) {
        boolean found = sampler[i].sample(vector, power, 3 * i, px, py, pz, out);
        return found ? out.dirX * nx + out.dirY * ny + out.dirZ * nz : 0;
    }

    private static void put(double[] array, int i, Vector3d v) {
        array[3 * i] = v.x();
        array[3 * i + 1] = v.y();
        array[3 * i + 2] = v.z();
    }
}
