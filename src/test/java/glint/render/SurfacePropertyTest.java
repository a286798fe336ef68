package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.geometry.Intersect;
import glint.image.FrameBuffer;
import glint.registry.MaterialType;
import glint.registry.Registry;
import glint.shading.Optics;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** Properties over seeded random inputs: no self-hits, unit directions, no energy gain. */
class SurfacePropertyTest {

    private static final long SEED = 20_201_122L;
    private static final double EPSILON = Renders.EPSILON;

    @Test
    void aRayLeavingASphereNeverReHitsItThere() {
        SplittableRandom random = new SplittableRandom(SEED);
        double[] refracted = new double[3];
        for (int i = 0; i < 200_000; i++) {
            double scale = Math.pow(10, random.nextDouble(-2, 7)); // positions from 0.01 to 10^7
            double cx = random.nextDouble(-1, 1) * scale, cy = random.nextDouble(-1, 1) * scale;
            double cz = random.nextDouble(-1, 1) * scale;
            double r = scale * random.nextDouble(1e-3, 1);
            double[] d = randomUnit(random);
            // start outside along -d, aim at a random point of the sphere's cross-section
            double[] o = {cx - 3 * r * d[0], cy - 3 * r * d[1], cz - 3 * r * d[2]};
            double[] aim = randomUnit(random);
            double k = random.nextDouble(0, 0.999) * r;
            double ax = cx + k * aim[0], ay = cy + k * aim[1], az = cz + k * aim[2];
            double[] dir = normalize(ax - o[0], ay - o[1], az - o[2]);
            double t = Intersect.sphereBefore(cx, cy, cz, r, o[0], o[1], o[2], dir[0], dir[1], dir[2],
                    Intersect.MISS);
            if (t == Intersect.MISS) {
                continue;
            }
            double[] n = normalize(o[0] + t * dir[0] - cx, o[1] + t * dir[1] - cy, o[2] + t * dir[2] - cz);
            double[] p = {cx + r * n[0], cy + r * n[1], cz + r * n[2]};
            double offset = EPSILON * Math.max(1, Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
            double cos = -(dir[0] * n[0] + dir[1] * n[1] + dir[2] * n[2]);
            // reflected: leaves the convex surface, must never meet the sphere again
            double[] refl = {dir[0] + 2 * cos * n[0], dir[1] + 2 * cos * n[1], dir[2] + 2 * cos * n[2]};
            assertEquals(1, Math.sqrt(refl[0] * refl[0] + refl[1] * refl[1] + refl[2] * refl[2]), 1e-12);
            double back = Intersect.sphereBefore(cx, cy, cz, r, p[0] + offset * n[0], p[1] + offset * n[1],
                    p[2] + offset * n[2], refl[0], refl[1], refl[2], Intersect.MISS);
            assertEquals(Intersect.MISS, back, () -> String.format(Locale.ROOT, "reflected ray re-hit (scale %g)", scale));
            // refracted: enters and must next meet the far side, 2 r cos(theta_t) away, not its own spot
            assertTrue(Optics.refract(dir[0], dir[1], dir[2], n[0], n[1], n[2], cos, 1 / 1.5, refracted));
            assertEquals(1, Math.sqrt(refracted[0] * refracted[0] + refracted[1] * refracted[1]
                    + refracted[2] * refracted[2]), 1e-12);
            double inside = Intersect.sphereBefore(cx, cy, cz, r, p[0] - offset * n[0], p[1] - offset * n[1],
                    p[2] - offset * n[2], refracted[0], refracted[1], refracted[2], Intersect.MISS);
            double cosT = -(refracted[0] * n[0] + refracted[1] * n[1] + refracted[2] * n[2]);
            assertEquals(2 * r * cosT, inside, 1e-6 * r + 4 * offset, "chord through the sphere");
        }
    }

    @Test
    void aRayLeavingAPlaneNeverReHitsIt() {
        SplittableRandom random = new SplittableRandom(SEED + 1);
        for (int i = 0; i < 200_000; i++) {
            double scale = Math.pow(10, random.nextDouble(-2, 7));
            double[] n = randomUnit(random);
            double[] q = {random.nextDouble(-1, 1) * scale, random.nextDouble(-1, 1) * scale,
                    random.nextDouble(-1, 1) * scale};
            double offsetOfPlane = n[0] * q[0] + n[1] * q[1] + n[2] * q[2];
            double[] o = {q[0] + scale * random.nextDouble(-1, 1), q[1] + scale * random.nextDouble(-1, 1),
                    q[2] + scale * random.nextDouble(-1, 1)};
            double[] dir = randomUnit(random);
            double t = Intersect.planeBefore(n[0], n[1], n[2], offsetOfPlane, o[0], o[1], o[2], dir[0], dir[1], dir[2],
                    Intersect.MISS);
            if (t == Intersect.MISS) {
                continue;
            }
            double[] p = {o[0] + t * dir[0], o[1] + t * dir[1], o[2] + t * dir[2]};
            double dist = n[0] * p[0] + n[1] * p[1] + n[2] * p[2] - offsetOfPlane;
            p[0] -= dist * n[0];
            p[1] -= dist * n[1];
            p[2] -= dist * n[2];
            double sign = (dir[0] * n[0] + dir[1] * n[1] + dir[2] * n[2]) < 0 ? 1 : -1; // facing normal
            double[] f = {sign * n[0], sign * n[1], sign * n[2]};
            double cos = -(dir[0] * f[0] + dir[1] * f[1] + dir[2] * f[2]);
            double offset = EPSILON * Math.max(1, Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
            double[] refl = {dir[0] + 2 * cos * f[0], dir[1] + 2 * cos * f[1], dir[2] + 2 * cos * f[2]};
            double again = Intersect.planeBefore(n[0], n[1], n[2], offsetOfPlane, p[0] + offset * f[0],
                    p[1] + offset * f[1], p[2] + offset * f[2], refl[0], refl[1], refl[2], Intersect.MISS);
            assertEquals(Intersect.MISS, again, "reflected ray re-hit the plane");
            double[] refracted = new double[3];
            if (Optics.refract(dir[0], dir[1], dir[2], f[0], f[1], f[2], cos, 1 / 1.5, refracted)) {
                double through = Intersect.planeBefore(n[0], n[1], n[2], offsetOfPlane, p[0] - offset * f[0],
                        p[1] - offset * f[1], p[2] - offset * f[2], refracted[0], refracted[1], refracted[2],
                        Intersect.MISS);
                assertEquals(Intersect.MISS, through, "refracted ray re-hit the plane");
            }
        }
    }

    @Test
    void fresnelSplitsEnergyWithoutGain() {
        SplittableRandom random = new SplittableRandom(SEED + 2);
        for (int i = 0; i < 100_000; i++) {
            double cos = random.nextDouble();
            double eta = random.nextDouble(0.2, 5);
            double f = Optics.fresnelDielectric(cos, eta);
            assertTrue(f >= 0 && f <= 1, "reflectance in [0, 1]");
            double s = Optics.schlick(random.nextDouble(), cos);
            assertTrue(s >= 0 && s <= 1, "Schlick in [0, 1]");
        }
    }

    @Test
    void aWhiteFurnaceNeverComesOutBrighterThanItsLight() {
        // Background radiance 1 everywhere, ambient 1, no point lights: every material with colour <= 1
        // can only pass on or lose energy, so no pixel may exceed 1.
        SplittableRandom random = new SplittableRandom(SEED + 3);
        for (int scene = 0; scene < 12; scene++) {
            StringBuilder yaml = new StringBuilder("""
                    camera: {position: [0, 1, -6], look_at: [0, 1, 0], fov: 70}
                    background: [1, 1, 1]
                    ambient: [1, 1, 1]
                    objects:
                    """);
            List<MaterialType> types = Registry.STANDARD.materials();
            for (int i = 0; i < 8; i++) {
                MaterialType type = types.get(random.nextInt(types.size()));
                StringBuilder sphere = new StringBuilder(String.format(Locale.ROOT,
                        "  - {type: sphere, center: [%f, %f, %f], radius: %f, material: {type: %s, color: [%f, %f, %f]",
                        random.nextDouble(-3, 3), random.nextDouble(0, 2.5), random.nextDouble(-1, 4),
                        random.nextDouble(0.2, 1.2), type.name(), random.nextDouble(), random.nextDouble(),
                        random.nextDouble()));
                for (String key : type.ownKeys()) { // a value the type declares for its own key (ior, roughness)
                    double[] values = type.sampleValues(key);
                    sphere.append(String.format(Locale.ROOT, ", %s: %f", key, values[random.nextInt(values.length)]));
                }
                yaml.append(sphere).append("}}\n");
            }
            for (Shading shading : Shading.values()) {
                FrameBuffer frame = Renders.render(yaml.toString(), 32, 24, 1, 8, shading);
                for (float v : frame.rgb()) {
                    assertTrue(v <= 1 + 1e-6 && v >= 0, "radiance " + v + " under " + shading + " in scene " + scene);
                }
            }
        }
    }

    private static double[] randomUnit(SplittableRandom random) {
        while (true) {
            double x = random.nextDouble(-1, 1), y = random.nextDouble(-1, 1), z = random.nextDouble(-1, 1);
            double len2 = x * x + y * y + z * z;
            if (len2 > 1e-4 && len2 <= 1) {
                return normalize(x, y, z);
            }
        }
    }

    private static double[] normalize(double x, double y, double z) {
        double len = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / len, y / len, z / len};
    }
}
