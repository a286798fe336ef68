package glint.shading;

import glint.math.Vector3d;
import glint.scene.Light;
import java.util.List;

/** A scene's lights in flat arrays, and one sampler per light type. */
public final class Lights {

    private final int count;
    private final boolean[] isPoint;
    /** Per light: a point light's position, or the unit direction towards a directional one. */
    private final double[] vector;
    /** Per light: colour x intensity. */
    private final double[] power;

    public Lights(List<Light> lights) {
        count = lights.size();
        isPoint = new boolean[count];
        vector = new double[3 * count];
        power = new double[3 * count];
        for (int i = 0; i < count; i++) {
            Light light = lights.get(i);
            if (light instanceof Light.Point point) {
                isPoint[i] = true;
                put(vector, i, point.position());
            } else {
                put(vector, i, ((Light.Directional) light).direction().scale(-1));
            }
            put(power, i, light.color().scale(light.intensity()));
        }
    }

    public int count() {
        return count;
    }

    /** Whether light i is a point light (else a directional one). */
    public boolean isPoint(int i) {
        return isPoint[i];
    }

    /** Coordinate {@code axis} (0 to 2) of point light i's position. */
    public double position(int i, int axis) {
        return vector[3 * i + axis];
    }

    /**
     * Light i seen from surface point p of unit normal n, into {@code out}; returns n.l, the cosine
     * at the surface, or 0 (leaving {@code out} alone) for a point light at p itself.
     */
    public double sample(int i, double px, double py, double pz, double nx, double ny, double nz, LightSample out) {
        boolean found = isPoint[i] ? samplePoint(i, px, py, pz, out) : sampleDirectional(i, out);
        return found ? out.dirX * nx + out.dirY * ny + out.dirZ * nz : 0;
    }

    /** A point light: inverse-square irradiance along the direction to it. */
    private boolean samplePoint(int i, double px, double py, double pz, LightSample out) {
        int j = 3 * i;
        double lx = vector[j] - px, ly = vector[j + 1] - py, lz = vector[j + 2] - pz;
        double distance2 = lx * lx + ly * ly + lz * lz;
        if (distance2 == 0) {
            return false;
        }
        double inv = 1 / Math.sqrt(distance2);
        out.distance = distance2 * inv;
        out.dirX = lx * inv;
        out.dirY = ly * inv;
        out.dirZ = lz * inv;
        double scale = inv * inv;
        out.irradianceR = power[j] * scale;
        out.irradianceG = power[j + 1] * scale;
        out.irradianceB = power[j + 2] * scale;
        return true;
    }

    /** A directional light: the same irradiance from the same direction everywhere. */
    private boolean sampleDirectional(int i, LightSample out) {
        int j = 3 * i;
        out.dirX = vector[j];
        out.dirY = vector[j + 1];
        out.dirZ = vector[j + 2];
        out.distance = Double.POSITIVE_INFINITY;
        out.irradianceR = power[j];
        out.irradianceG = power[j + 1];
        out.irradianceB = power[j + 2];
        return true;
    }

    private static void put(double[] array, int i, Vector3d v) {
        array[3 * i] = v.x();
        array[3 * i + 1] = v.y();
        array[3 * i + 2] = v.z();
    }
}
