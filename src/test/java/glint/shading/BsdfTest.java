package glint.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.math.Vector3d;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Each BSDF's three answers checked against each other and against numbers worked out apart from
 * them, as pbrt's and Mitsuba's BSDF tests do: its samples distributed as its pdf (a chi-square test
 * on seeded samples), the pdf integrating to the chance that a sample is drawn, the weight equal to
 * f cos / pdf, reciprocity, and a white surface that never gives back more light than it receives.
 */
class BsdfTest {

    /** The lobes under test: matte, and metal from nearly a mirror to very rough, seen from several angles. */
    static Stream<Arguments> lobes() {
        return Stream.of(
                Arguments.of("matte", new Lambert(), 0.0, 0.9), Arguments.of("matte", new Lambert(), 0.0, 0.2),
                Arguments.of("metal", new Conductor(), 0.1, 0.9), Arguments.of("metal", new Conductor(), 0.3, 0.7),
                Arguments.of("metal", new Conductor(), 0.6, 0.4), Arguments.of("metal", new Conductor(), 0.9, 0.1),
                Arguments.of("metal", new Conductor(), 0.3, 0.05));
    }

    /** A surface at the origin whose normal is tilted off every axis, so no test relies on n = +z. */
    static final double[] NORMAL = unit(0.3, 0.8, -0.5);

    static Materials materials(Bsdf bsdf, double roughness, double color) {
        return Materials.of(List.of(new Materials.Parameters(bsdf, new Vector3d(color, color, color), 1, 0, 0, 1, 1.5,
                roughness)));
    }

    static Surface surface() {
        Surface s = new Surface();
        s.nx = NORMAL[0];
        s.ny = NORMAL[1];
        s.nz = NORMAL[2];
        s.front = true;
        s.material = 0;
        return s;
    }

    /** A unit direction at cosine {@code cos} to the normal. */
    static double[] outgoing(double cos) {
        ShadingFrame frame = new ShadingFrame();
        frame.set(NORMAL[0], NORMAL[1], NORMAL[2]);
        double sin = Math.sqrt(1 - cos * cos);
        double x = sin * Math.cos(0.7), y = sin * Math.sin(0.7);
        return new double[] {frame.worldX(x, y, cos), frame.worldY(x, y, cos), frame.worldZ(x, y, cos)};
    }

    @ParameterizedTest(name = "{0} roughness {2}, cos {3}")
    @MethodSource("lobes")
    void samplesAreDistributedAsThePdfSays(String name, Bsdf bsdf, double roughness, double cosOut) {
        Materials m = materials(bsdf, roughness, 0.8);
        Surface s = surface();
        double[] wo = outgoing(cosOut);
        s.cosIncident = cosOut;
        ShadingFrame frame = new ShadingFrame();
        frame.set(NORMAL[0], NORMAL[1], NORMAL[2]);
        int thetaBins = 10, phiBins = 20, samples = 200_000;
        double[] observed = new double[thetaBins * phiBins];
        BsdfSample out = new BsdfSample();
        SplittableRandom random = new SplittableRandom(7);
        for (int i = 0; i < samples; i++) {
            if (bsdf.sample(m, s, wo[0], wo[1], wo[2], random.nextDouble(), random.nextDouble(), random.nextDouble(),
                    out)) {
                double z = frame.localZ(out.wiX, out.wiY, out.wiZ);
                double phi = Math.atan2(frame.localY(out.wiX, out.wiY, out.wiZ), frame.localX(out.wiX, out.wiY, out.wiZ));
                int t = Math.min(thetaBins - 1, (int) ((1 - z) * thetaBins)); // bins equal in cos theta
                int p = Math.min(phiBins - 1, (int) ((phi + Math.PI) / (2 * Math.PI) * phiBins));
                observed[t * phiBins + p]++;
            }
        }
        // expected counts: the pdf integrated over each bin by the midpoint rule on a fine grid
        double[] expected = new double[thetaBins * phiBins];
        int sub = 96, subZ = 96;
        for (int t = 0; t < thetaBins; t++) {
            for (int p = 0; p < phiBins; p++) {
                double sum = 0;
                for (int a = 0; a < subZ; a++) {
                    for (int b = 0; b < sub; b++) {
                        double z = 1 - (t + (a + 0.5) / subZ) / thetaBins;
                        double phi = -Math.PI + (p + (b + 0.5) / sub) / phiBins * 2 * Math.PI;
                        double r = Math.sqrt(Math.max(0, 1 - z * z));
                        double x = r * Math.cos(phi), y = r * Math.sin(phi);
                        sum += bsdf.pdf(m, s, wo[0], wo[1], wo[2], frame.worldX(x, y, z), frame.worldY(x, y, z),
                                frame.worldZ(x, y, z));
                    }
                }
                double binSolidAngle = (1.0 / thetaBins) * (2 * Math.PI / phiBins);
                expected[t * phiBins + p] = sum / (subZ * sub) * binSolidAngle * samples;
            }
        }
        // Pearson's statistic over the bins expected to hold at least 5 samples, the rest pooled
        double chi2 = 0, pooledObserved = 0, pooledExpected = 0;
        int bins = 0;
        for (int i = 0; i < expected.length; i++) {
            if (expected[i] < 5) {
                pooledObserved += observed[i];
                pooledExpected += expected[i];
                continue;
            }
            chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
            bins++;
        }
        if (pooledExpected >= 5) {
            chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
            bins++;
        }
        // the 0.1 % critical value of chi-square with k degrees of freedom (Wilson-Hilferty)
        int k = bins - 1;
        double z = 3.09, c = 1 - 2.0 / (9 * k) + z * Math.sqrt(2.0 / (9 * k));
        double critical = k * c * c * c;
        assertTrue(bins > 20, "enough bins to test: " + bins);
        assertTrue(chi2 < critical, "chi-square " + chi2 + " over " + k + " degrees of freedom, critical " + critical);
    }

    @ParameterizedTest(name = "{0} roughness {2}, cos {3}")
    @MethodSource("lobes")
    void theWeightIsFCosOverPdfAndThePdfIntegratesToTheChanceOfASample(String name, Bsdf bsdf, double roughness,
                                                                        double cosOut) {
        Materials m = materials(bsdf, roughness, 0.7);
        Surface s = surface();
        s.cosIncident = cosOut;
        double[] wo = outgoing(cosOut);
        BsdfSample out = new BsdfSample();
        Rgb f = new Rgb();
        SplittableRandom random = new SplittableRandom(11);
        int drawn = 0, tries = 100_000;
        for (int i = 0; i < tries; i++) {
            if (!bsdf.sample(m, s, wo[0], wo[1], wo[2], random.nextDouble(), random.nextDouble(), random.nextDouble(),
                    out)) {
                continue;
            }
            drawn++;
            assertFalse(out.delta());
            double cosIn = out.wiX * NORMAL[0] + out.wiY * NORMAL[1] + out.wiZ * NORMAL[2];
            assertTrue(cosIn > 0, "a sample on the normal's side");
            bsdf.evaluate(m, s, wo[0], wo[1], wo[2], out.wiX, out.wiY, out.wiZ, f);
            double pdf = bsdf.pdf(m, s, wo[0], wo[1], wo[2], out.wiX, out.wiY, out.wiZ);
            assertEquals(pdf, out.pdf, 1e-9 * pdf);
            assertEquals(f.r * cosIn / pdf, out.weightR, 1e-9 * out.weightR);
        }
        double integral = hemisphereIntegral((x, y, z) -> bsdf.pdf(m, s, wo[0], wo[1], wo[2], x, y, z));
        double chance = (double) drawn / tries;
        assertEquals(chance, integral, 4 * Math.sqrt(chance * (1 - chance) / tries) + 2e-3,
                "the pdf over the hemisphere is the chance a direction is drawn");
    }

    @ParameterizedTest(name = "{0} roughness {2}, cos {3}")
    @MethodSource("lobes")
    void fIsReciprocal(String name, Bsdf bsdf, double roughness, double cosOut) {
        Materials m = materials(bsdf, roughness, 0.6);
        Surface s = surface();
        SplittableRandom random = new SplittableRandom(3);
        Rgb there = new Rgb(), back = new Rgb();
        for (int i = 0; i < 1000; i++) {
            double[] a = outgoing(0.02 + 0.98 * random.nextDouble()), b = outgoing(0.02 + 0.98 * random.nextDouble());
            // turn b about the normal so the pair is not coplanar with it
            ShadingFrame frame = new ShadingFrame();
            frame.set(NORMAL[0], NORMAL[1], NORMAL[2]);
            double phi = 2 * Math.PI * random.nextDouble(), z = frame.localZ(b[0], b[1], b[2]);
            double r = Math.sqrt(1 - z * z);
            double[] c = {frame.worldX(r * Math.cos(phi), r * Math.sin(phi), z),
                    frame.worldY(r * Math.cos(phi), r * Math.sin(phi), z), frame.worldZ(r * Math.cos(phi), r * Math.sin(phi), z)};
            bsdf.evaluate(m, s, a[0], a[1], a[2], c[0], c[1], c[2], there);
            bsdf.evaluate(m, s, c[0], c[1], c[2], a[0], a[1], a[2], back);
            assertEquals(there.r, back.r, 1e-12 * Math.max(1, there.r));
        }
    }

    @ParameterizedTest(name = "{0} roughness {2}, cos {3}")
    @MethodSource("lobes")
    void aWhiteSurfaceGivesBackNoMoreThanItReceivesAndItsSamplesSayHowMuch(String name, Bsdf bsdf, double roughness,
                                                                           double cosOut) {
        Materials m = materials(bsdf, roughness, 1);
        Surface s = surface();
        s.cosIncident = cosOut;
        double[] wo = outgoing(cosOut);
        Rgb f = new Rgb();
        // the directional albedo: the integral of f cos over the hemisphere, by quadrature
        double albedo = hemisphereIntegral((x, y, z) -> {
            bsdf.evaluate(m, s, wo[0], wo[1], wo[2], x, y, z, f);
            return f.r * (x * NORMAL[0] + y * NORMAL[1] + z * NORMAL[2]);
        });
        assertTrue(albedo <= 1 + 2e-3, "energy never grows: " + albedo);
        if (bsdf instanceof Lambert) {
            assertEquals(1, albedo, 2e-3);
        }
        // and the mean weight of its samples (a sample not drawn counts 0) is the same albedo
        BsdfSample out = new BsdfSample();
        SplittableRandom random = new SplittableRandom(5);
        int n = 200_000;
        double sum = 0, sum2 = 0;
        for (int i = 0; i < n; i++) {
            double w = bsdf.sample(m, s, wo[0], wo[1], wo[2], random.nextDouble(), random.nextDouble(),
                    random.nextDouble(), out) ? out.weightR : 0;
            assertTrue(w <= 1 + 1e-12, "a white surface's weight is at most 1: " + w);
            sum += w;
            sum2 += w * w;
        }
        double mean = sum / n, error = Math.sqrt((sum2 / n - mean * mean) / n);
        assertEquals(albedo, mean, 4 * error + 2e-3);
    }

    interface Integrand {
        double at(double x, double y, double z);
    }

    /**
     * The integral over the normal's hemisphere per solid angle, by the midpoint rule in (cos theta,
     * phi) on a grid fine enough for the narrowest lobe tested, denser near the normal and the horizon
     * (where a grazing view's lobe lies).
     */
    static double hemisphereIntegral(Integrand g) {
        ShadingFrame frame = new ShadingFrame();
        frame.set(NORMAL[0], NORMAL[1], NORMAL[2]);
        int nu = 3000, nPhi = 2400;
        double sum = 0;
        for (int i = 0; i < nu; i++) {
            // z = (1 - cos(pi u)) / 2 puts more cells at both ends; dz = pi/2 sin(pi u) du
            double u = (i + 0.5) / nu, z = (1 - Math.cos(Math.PI * u)) / 2, dz = Math.PI / 2 * Math.sin(Math.PI * u) / nu;
            double r = Math.sqrt(Math.max(0, 1 - z * z));
            for (int j = 0; j < nPhi; j++) {
                double phi = (j + 0.5) / nPhi * 2 * Math.PI;
                double x = r * Math.cos(phi), y = r * Math.sin(phi);
                sum += g.at(frame.worldX(x, y, z), frame.worldY(x, y, z), frame.worldZ(x, y, z)) * dz;
            }
        }
        return sum * 2 * Math.PI / nPhi;
    }

    private static double[] unit(double x, double y, double z) {
        double l = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / l, y / l, z / l};
    }
}
