package glint.registry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import glint.input.InputException;
import glint.scene.Light;
import glint.scenefile.SceneLoader;
import glint.shading.LightRay;
import glint.shading.LightSample;
import glint.shading.Lights;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The contract every registered light type is held to, without being listed: each is written in a
 * scene file with values for its keys (taken by key name from {@link #VALUES}: a type with a key
 * that has none fails, so a new type cannot go untested), compiled, and its sampler checked on
 * seeded random points: a sampled direction's density is what {@code pdf} answers for it; the
 * density integrates to 1 over the directions it covers and is 0 off them; the irradiance its
 * samples stand for, summed over a sphere around the light, is its power, and so is the mean flux of
 * the light leaving it.
 */
class LightTypeContractTest {

    /** Values to write for each key a light type reads besides type, color and intensity: each is tried. */
    private static final Map<String, List<String>> VALUES = Map.of(
            "position", List.of("[0.3, 0.2, -0.4]"),
            "direction", List.of("[0.2, -1, 0.3]"),
            "radius", List.of("0", "0.4", "1e-4"),
            "angle", List.of("0", "0.53", "30", "120"));

    /** The radius of the sphere around the origin on which the light is seen and its flux counted. */
    private static final double SPHERE = 6;

    record Case(String yaml, Lights lights) {
        @Override
        public String toString() {
            return yaml;
        }
    }

    static Stream<Case> lights() throws InputException {
        List<Case> cases = new ArrayList<>();
        for (LightType<?> type : Registry.STANDARD.lights()) {
            List<String> mappings = new ArrayList<>(List.of("type: " + type.name() + ", color: [1, 0.5, 0.25], intensity: 3"));
            for (String key : type.keys()) {
                List<String> values = VALUES.get(key);
                if (values == null) {
                    fail("light type " + type.name() + " reads key " + key + ", which this test has no values for");
                }
                List<String> grown = new ArrayList<>();
                for (String mapping : mappings) {
                    for (String value : values) {
                        grown.add(mapping + ", " + key + ": " + value);
                    }
                }
                mappings = grown;
            }
            for (String mapping : mappings) {
                String yaml = "lights:\n  - {" + mapping + "}\n";
                Light light = SceneLoader.parse("light.yaml", yaml).lights().get(0);
                cases.add(new Case(mapping, Lights.of(List.of(Registry.STANDARD.typeOf(light).compile(light).light()))));
            }
        }
        return cases.stream();
    }

    @ParameterizedTest
    @MethodSource("lights")
    void aSampledDirectionHasTheDensityPdfAnswersAndPointsAtTheLight(Case c) {
        Lights lights = c.lights();
        Random random = new Random(1);
        LightSample out = new LightSample();
        for (int k = 0; k < 2000; k++) {
            double[] p = pointOnSphere(random, SPHERE);
            if (!lights.sample(0, p[0], p[1], p[2], random.nextDouble(), random.nextDouble(), out)) {
                fail("no direction from " + p[0] + ", " + p[1] + ", " + p[2]);
            }
            assertEquals(1, out.dirX * out.dirX + out.dirY * out.dirY + out.dirZ * out.dirZ, 1e-12);
            assertTrue(out.distance > 0, "distance " + out.distance);
            assertTrue(out.irradianceR >= 0 && out.irradianceG >= 0 && out.irradianceB >= 0);
            if (lights.isDelta(0)) {
                assertEquals(0, out.pdf);
                assertEquals(0, lights.pdf(0, p[0], p[1], p[2], out.dirX, out.dirY, out.dirZ));
            } else {
                double pdf = lights.pdf(0, p[0], p[1], p[2], out.dirX, out.dirY, out.dirZ);
                assertEquals(out.pdf, pdf, 1e-9 * out.pdf, "the density of a sampled direction");
            }
        }
    }

    /**
     * Over a cone around the sampled directions twice as wide as they spread, the density's mean
     * times the cone's solid angle is 1; outside it the density is 0.
     */
    @ParameterizedTest
    @MethodSource("lights")
    void theDensityIntegratesToOneOverTheDirectionsItCovers(Case c) {
        Lights lights = c.lights();
        if (lights.isDelta(0)) {
            return;
        }
        Random random = new Random(2);
        LightSample out = new LightSample();
        for (int point = 0; point < 5; point++) {
            double[] p = pointOnSphere(random, SPHERE);
            // the axis: the mean sampled direction; the cone: twice the widest angle off it
            double ax = 0, ay = 0, az = 0;
            double[][] dirs = new double[400][];
            for (int k = 0; k < dirs.length; k++) {
                lights.sample(0, p[0], p[1], p[2], random.nextDouble(), random.nextDouble(), out);
                dirs[k] = new double[] {out.dirX, out.dirY, out.dirZ};
                ax += out.dirX;
                ay += out.dirY;
                az += out.dirZ;
            }
            double norm = Math.sqrt(ax * ax + ay * ay + az * az);
            ax /= norm;
            ay /= norm;
            az /= norm;
            double widest = 0;
            for (double[] d : dirs) {
                widest = Math.max(widest, Math.acos(Math.min(1, d[0] * ax + d[1] * ay + d[2] * az)));
            }
            double cone = Math.min(Math.PI, 2 * widest);
            double oneMinusCos = 1 - Math.cos(cone);
            int n = 200_000;
            double sum = 0;
            for (int k = 0; k < n; k++) {
                double[] w = inCone(random, ax, ay, az, oneMinusCos);
                sum += lights.pdf(0, p[0], p[1], p[2], w[0], w[1], w[2]);
            }
            double integral = sum / n * 2 * Math.PI * oneMinusCos;
            assertEquals(1, integral, 0.02, c + ": the density's integral from a point " + point);
            if (cone < Math.PI) {
                for (int k = 0; k < 1000; k++) {
                    double[] w = pointOnSphere(random, 1);
                    if (w[0] * ax + w[1] * ay + w[2] * az < Math.cos(cone)) {
                        assertEquals(0, lights.pdf(0, p[0], p[1], p[2], w[0], w[1], w[2]));
                    }
                }
            }
        }
    }

    /**
     * The flux through a sphere around the light, counted from the light's samples (the irradiance
     * each stands for, times the cosine at the sphere's inward normal, over the sphere's area), is the
     * power the light says it has.
     */
    @ParameterizedTest
    @MethodSource("lights")
    void theIrradianceOfItsSamplesOverASphereAroundItIsItsPower(Case c) {
        Lights lights = c.lights();
        Random random = new Random(3);
        LightSample out = new LightSample();
        int n = 100_000;
        double flux = 0;
        for (int k = 0; k < n; k++) {
            double[] p = pointOnSphere(random, SPHERE);
            if (lights.sample(0, p[0], p[1], p[2], random.nextDouble(), random.nextDouble(), out)) {
                double cosine = -(out.dirX * p[0] + out.dirY * p[1] + out.dirZ * p[2]) / SPHERE;
                flux += Math.max(0, cosine) * (out.irradianceR + out.irradianceG + out.irradianceB) / 3;
            }
        }
        flux *= 4 * Math.PI * SPHERE * SPHERE / n;
        double power = lights.power(0, SPHERE);
        assertEquals(power, flux, 0.02 * power, c + ": flux through the sphere against the power");
    }

    /**
     * Light leaving it: the flux its rays stand for is the same for each, as LightTargets needs, and
     * averages to its power, and each ray, followed back
     * from a point on it, comes from the light as its sample from that point sees it (the direction a
     * delta light's sample gives; a direction of non-zero density for a light with a size).
     */
    @ParameterizedTest
    @MethodSource("lights")
    void theFluxOfTheLightLeavingItIsItsPowerAlongDirectionsItsSampleSees(Case c) {
        Lights lights = c.lights();
        Random random = new Random(5);
        LightRay ray = new LightRay();
        LightSample seen = new LightSample();
        int n = 100_000;
        double flux = 0, first = Double.NaN;
        for (int k = 0; k < n; k++) {
            lights.leaving(0, 0, 0, 0, SPHERE, random.nextDouble(), random.nextDouble(), random.nextDouble(),
                    random.nextDouble(), ray);
            double rayFlux = (ray.fluxR + ray.fluxG + ray.fluxB) / 3;
            first = k == 0 ? rayFlux : first;
            assertEquals(first, rayFlux, 1e-12 * first, c + ": every ray leaving it carries the same flux");
            flux += rayFlux;
            assertEquals(1, ray.dirX * ray.dirX + ray.dirY * ray.dirY + ray.dirZ * ray.dirZ, 1e-12);
            assertTrue(ray.pdfOrigin > 0 && ray.pdfDirection > 0);
            if (k % 100 == 0) {
                double px = ray.originX + 2 * ray.dirX, py = ray.originY + 2 * ray.dirY, pz = ray.originZ + 2 * ray.dirZ;
                if (lights.isDelta(0)) {
                    assertTrue(lights.sample(0, px, py, pz, 0.5, 0.5, seen));
                    assertEquals(-1, seen.dirX * ray.dirX + seen.dirY * ray.dirY + seen.dirZ * ray.dirZ, 1e-9);
                } else {
                    assertTrue(lights.pdf(0, px, py, pz, -ray.dirX, -ray.dirY, -ray.dirZ) > 0,
                            c + ": a ray leaving it, seen from along it");
                }
            }
        }
        flux /= n;
        double power = lights.power(0, SPHERE);
        assertEquals(power, flux, 0.02 * power, c + ": mean flux of the light leaving it against its power");
    }

    /** A light with a size whose size goes to 0 lights a point as the delta light it becomes. */
    @ParameterizedTest
    @MethodSource("lights")
    void aTinyLightLightsAsItsDeltaLight(Case c) throws InputException {
        if (!c.yaml().contains("radius: 1e-4")) {
            return;
        }
        Lights tiny = c.lights();
        Lights point = lights().filter(other -> other.yaml().equals(c.yaml().replace("radius: 1e-4", "radius: 0")))
                .findFirst().orElseThrow().lights();
        assertFalse(tiny.isDelta(0));
        assertTrue(point.isDelta(0));
        Random random = new Random(4);
        LightSample a = new LightSample(), b = new LightSample();
        for (int k = 0; k < 100; k++) {
            double[] p = pointOnSphere(random, SPHERE);
            tiny.sample(0, p[0], p[1], p[2], random.nextDouble(), random.nextDouble(), a);
            point.sample(0, p[0], p[1], p[2], 0, 0, b);
            assertEquals(b.irradianceR, a.irradianceR, 1e-8 * b.irradianceR);
            assertEquals(1, a.dirX * b.dirX + a.dirY * b.dirY + a.dirZ * b.dirZ, 1e-9);
        }
    }

    private static double[] pointOnSphere(Random random, double radius) {
        double z = 2 * random.nextDouble() - 1, phi = 2 * Math.PI * random.nextDouble();
        double r = Math.sqrt(1 - z * z);
        return new double[] {radius * r * Math.cos(phi), radius * r * Math.sin(phi), radius * z};
    }

    /** A direction uniform in the cone of 1 - cos = {@code oneMinusCos} around unit axis a. */
    private static double[] inCone(Random random, double ax, double ay, double az, double oneMinusCos) {
        double cos = 1 - random.nextDouble() * oneMinusCos, phi = 2 * Math.PI * random.nextDouble();
        double sin = Math.sqrt(Math.max(0, 1 - cos * cos));
        // any two unit vectors perpendicular to a
        double tx = Math.abs(ax) < 0.9 ? 1 : 0, ty = Math.abs(ax) < 0.9 ? 0 : 1, tz = 0;
        double d = tx * ax + ty * ay + tz * az;
        tx -= d * ax;
        ty -= d * ay;
        tz -= d * az;
        double tn = Math.sqrt(tx * tx + ty * ty + tz * tz);
        tx /= tn;
        ty /= tn;
        tz /= tn;
        double bx = ay * tz - az * ty, by = az * tx - ax * tz, bz = ax * ty - ay * tx;
        double x = sin * Math.cos(phi), y = sin * Math.sin(phi);
        return new double[] {x * tx + y * bx + cos * ax, x * ty + y * by + cos * ay, x * tz + y * bz + cos * az};
    }
}
