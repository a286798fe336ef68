package glint.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import glint.math.Vector3d;
import glint.recipe.GlowType;
import glint.registry.MaterialType;
import glint.registry.Registry;
import glint.scene.Material;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.function.Supplier;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The contract every registered material type's {@link Bsdf} keeps, checked on every type of
 * {@link Registry#STANDARD} and the test recipe's glow ({@link GlowType}, whose key {@code strength} no
 * shipped type reads) at the values each declares for its own keys ({@link MaterialType#samples}),
 * from both sides of the surface and two view angles, without a list of types here (as Mitsuba 3's BSDF
 * tests): its non-delta samples distributed as its pdf over the whole sphere (a chi-square test), the pdf
 * integrating to the chance of such a sample (at most 1), the weight equal to f |cos| / pdf, f reciprocal
 * (through the surface in the form Glint's unscaled radiance gives it, below), and a white surface giving
 * back no more light than it receives, and light of its own only where it says it emits. Seeded, so every
 * run draws the same numbers.
 */
class BsdfContractTest {

    /** The types tested: the shipped ones and the recipe's, added as a scene file's reader would add it. */
    static final Registry REGISTRY = Registry.STANDARD.with(GlowType.TYPE);

    /** The views tested: the cosine of wo to the normal, near the normal and towards the horizon. */
    static final double[] VIEWS = {0.85, 0.3};
    /** Samples drawn per case, for the chi-square test and the white furnace. */
    static final int SAMPLES = 100_000;
    /**
     * The quadrature grid over the sphere (cells uniform in cos theta and phi) that integrates the pdf
     * over each chi-square bin, fine enough for the narrowest lobes the types declare (roughness 0.2,
     * GGX alpha 0.04). Measured on this test: at 600 x 300 the pdf's integral of 8 of the roughness-0.2
     * cases strayed beyond the tolerance (up to 0.4 %), at 300 x 150 their chi-squares failed too; the
     * metal's roughness 0.1 at cos 0.3 needed more than this grid (its integral came out 7 % short).
     */
    static final int GRID_Z = 1200, GRID_PHI = 600;
    /** The chi-square bins: equal in cos theta over [-1, 1], and in phi. */
    static final int BINS_Z = 20, BINS_PHI = 20;

    /** A surface at the origin whose normal is tilted off every axis, so no test relies on n = +z. */
    static final double[] NORMAL = unit(0.3, 0.8, -0.5);

    /** One case: a material of a registered type, the side met and the view. */
    record Case(MaterialType type, Material material, boolean front, double cosOut) {
        @Override
        public String toString() {
            return type.name() + " " + material.parameters() + (front ? " front" : " back") + " cos " + cosOut;
        }
    }

    static Stream<Arguments> cases() {
        List<Arguments> cases = new ArrayList<>();
        for (MaterialType type : REGISTRY.materials()) {
            for (Material material : type.samples()) {
                for (boolean front : new boolean[] {true, false}) {
                    for (double cos : VIEWS) {
                        cases.add(Arguments.of(new Case(type, material, front, cos)));
                    }
                }
            }
        }
        return cases.stream();
    }

    /** A type that reads a key of its own must say which values to sample it at: none is left untested. */
    @Test
    void everyRegisteredTypeDeclaresValuesForEachKeyOfItsOwn() {
        for (MaterialType type : REGISTRY.materials()) {
            for (String key : type.ownKeys()) {
                if (type.sampleValues(key).length == 0) {
                    fail("material type " + type.name() + " reads " + key + " but declares no values to sample it at "
                            + "(MaterialType.sampledAt)");
                }
            }
            assertFalse(type.samples().isEmpty(), type.name());
        }
    }

    /** The case's material, of grey {@code color}, compiled by its type. */
    static Materials materials(Case c, double color) {
        Material m = c.material();
        return Materials.of(List.of(c.type().compile(new Material(m.type(), new Vector3d(color, color, color), m.kd(),
                m.ks(), m.kt(), m.shininess(), m.parameters()))));
    }

    /** The surface met: its normal faces wo; from the back the normal is the outward one reversed. */
    static Surface surface(Case c) {
        Surface s = new Surface();
        s.nx = NORMAL[0];
        s.ny = NORMAL[1];
        s.nz = NORMAL[2];
        s.front = c.front();
        s.cosIncident = c.cosOut();
        s.material = 0;
        return s;
    }

    static ShadingFrame frame() {
        ShadingFrame frame = new ShadingFrame();
        frame.set(NORMAL[0], NORMAL[1], NORMAL[2]);
        return frame;
    }

    /** A unit direction at cosine {@code cos} to the normal, azimuth {@code phi}. */
    static double[] direction(double cos, double phi) {
        ShadingFrame frame = frame();
        double sin = Math.sqrt(Math.max(0, 1 - cos * cos));
        double x = sin * Math.cos(phi), y = sin * Math.sin(phi);
        return new double[] {frame.worldX(x, y, cos), frame.worldY(x, y, cos), frame.worldZ(x, y, cos)};
    }

    private static double dot(double[] a, double x, double y, double z) {
        return a[0] * x + a[1] * y + a[2] * z;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void samplesAreDistributedAsThePdfSaysOverTheWholeSphereAndItIntegratesToTheirChance(Case c) {
        Materials m = materials(c, 0.8);
        Bsdf bsdf = m.bsdf(0);
        Surface s = surface(c);
        double[] wo = direction(c.cosOut(), 0.7);
        ShadingFrame frame = frame();
        double[] observed = new double[BINS_Z * BINS_PHI];
        BsdfSample out = new BsdfSample();
        SplittableRandom random = new SplittableRandom(7);
        int nonDelta = 0;
        for (int i = 0; i < SAMPLES; i++) {
            if (!bsdf.sample(m, s, wo[0], wo[1], wo[2], random.nextDouble(), random.nextDouble(), random.nextDouble(),
                    out) || out.delta()) {
                continue;
            }
            nonDelta++;
            observed[bin(frame, out.wiX, out.wiY, out.wiZ)]++;
        }
        if (Lobe.allDelta(m.lobes(0))) {
            assertEquals(0, nonDelta, "a material whose lobes are all delta samples none that is not");
            return;
        }
        double[] expected = expectedCounts(bsdf, m, s, wo, frame);
        double integral = 0;
        for (double e : expected) {
            integral += e / SAMPLES;
        }
        double chance = (double) nonDelta / SAMPLES;
        assertTrue(integral <= 1 + 2e-3, "the pdf integrates to at most 1: " + integral);
        assertEquals(chance, integral, 4 * Math.sqrt(chance * (1 - chance) / SAMPLES) + 2e-3,
                "the pdf over the sphere is the chance a non-delta direction is drawn");
        double[] chi = chiSquare(observed, expected);
        assertTrue(chi[1] > 20, "enough bins to test: " + chi[1]);
        assertTrue(chi[0] < critical((int) chi[1] - 1), "chi-square " + chi[0] + " over " + (chi[1] - 1)
                + " degrees of freedom, critical " + critical((int) chi[1] - 1));
    }

    /** The bin of a direction: equal steps of cos theta from 1 down to -1, and of phi. */
    private static int bin(ShadingFrame frame, double x, double y, double z) {
        double cos = frame.localZ(x, y, z);
        double phi = Math.atan2(frame.localY(x, y, z), frame.localX(x, y, z));
        int t = Math.max(0, Math.min(BINS_Z - 1, (int) ((1 - cos) / 2 * BINS_Z)));
        int p = Math.max(0, Math.min(BINS_PHI - 1, (int) ((phi + Math.PI) / (2 * Math.PI) * BINS_PHI)));
        return t * BINS_PHI + p;
    }

    /** The pdf integrated over each bin (midpoint rule on the grid), times the samples drawn. */
    private static double[] expectedCounts(Bsdf bsdf, Materials m, Surface s, double[] wo, ShadingFrame frame) {
        double[] expected = new double[BINS_Z * BINS_PHI];
        double cell = (2.0 / GRID_Z) * (2 * Math.PI / GRID_PHI);
        for (int a = 0; a < GRID_Z; a++) {
            double z = 1 - 2 * (a + 0.5) / GRID_Z, r = Math.sqrt(Math.max(0, 1 - z * z));
            for (int b = 0; b < GRID_PHI; b++) {
                double phi = -Math.PI + 2 * Math.PI * (b + 0.5) / GRID_PHI;
                double x = r * Math.cos(phi), y = r * Math.sin(phi);
                double wx = frame.worldX(x, y, z), wy = frame.worldY(x, y, z), wz = frame.worldZ(x, y, z);
                int t = a * BINS_Z / GRID_Z, p = b * BINS_PHI / GRID_PHI;
                expected[t * BINS_PHI + p] += bsdf.pdf(m, s, wo[0], wo[1], wo[2], wx, wy, wz) * cell * SAMPLES;
            }
        }
        return expected;
    }

    /** Pearson's statistic over the bins expected to hold at least 5 samples, the rest pooled; and the bins. */
    private static double[] chiSquare(double[] observed, double[] expected) {
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
        return new double[] {chi2, bins};
    }

    /** The 0.1 % critical value of chi-square with k degrees of freedom (Wilson-Hilferty). */
    private static double critical(int k) {
        double z = 3.09, c = 1 - 2.0 / (9 * k) + z * Math.sqrt(2.0 / (9 * k));
        return k * c * c * c;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void aSamplesWeightIsFCosOverPdfAndItsLobeIsOneTheMaterialHas(Case c) {
        Materials m = materials(c, 0.7);
        Bsdf bsdf = m.bsdf(0);
        Surface s = surface(c);
        double[] wo = direction(c.cosOut(), 0.7);
        BsdfSample out = new BsdfSample();
        Rgb f = new Rgb();
        SplittableRandom random = new SplittableRandom(11);
        for (int i = 0; i < 20_000; i++) {
            if (!bsdf.sample(m, s, wo[0], wo[1], wo[2], random.nextDouble(), random.nextDouble(), random.nextDouble(),
                    out)) {
                continue;
            }
            int n = i;
            Supplier<String> at = () -> c + ", sample " + n;
            assertEquals(1, Math.sqrt(out.wiX * out.wiX + out.wiY * out.wiY + out.wiZ * out.wiZ), 1e-12, at);
            assertTrue(Integer.bitCount(out.lobe) == 1 && (out.lobe & m.lobes(0)) != 0,
                    () -> "lobe " + out.lobe + " among the material's " + m.lobes(0) + " at " + at.get());
            double cosIn = dot(NORMAL, out.wiX, out.wiY, out.wiZ);
            assertEquals(out.transmitted(), cosIn < 0, at);
            if (out.delta()) {
                assertEquals(0, out.pdf, at);
                continue;
            }
            bsdf.evaluate(m, s, wo[0], wo[1], wo[2], out.wiX, out.wiY, out.wiZ, f);
            double pdf = bsdf.pdf(m, s, wo[0], wo[1], wo[2], out.wiX, out.wiY, out.wiZ);
            assertEquals(pdf, out.pdf, 1e-7 * pdf, at);
            assertEquals(f.r * Math.abs(cosIn) / pdf, out.weightR, 1e-7 * out.weightR, at);
            assertEquals(f.b * Math.abs(cosIn) / pdf, out.weightB, 1e-7 * out.weightB, at);
        }
    }

    /**
     * f(a, b) n_a^2 = f(b, a) n_b^2, n_a the index on a's side (1 outside, the material's ior inside): the
     * reciprocity of a reflection (same index), and a transmission's as Glint carries radiance unscaled
     * (no eta^2; docs/conventions.md). f(b, a) is the surface met from b's side, its normal turned.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void fIsReciprocal(Case c) {
        Materials m = materials(c, 0.6);
        Bsdf bsdf = m.bsdf(0);
        Surface s = surface(c), turned = surface(c);
        turned.nx = -NORMAL[0];
        turned.ny = -NORMAL[1];
        turned.nz = -NORMAL[2];
        turned.front = !c.front();
        double inside = m.ior(0) * m.ior(0);
        double here = c.front() ? 1 : inside, there = c.front() ? inside : 1;
        SplittableRandom random = new SplittableRandom(3);
        Rgb forth = new Rgb(), back = new Rgb();
        for (int i = 0; i < 2000; i++) {
            double[] a = direction(0.02 + 0.98 * random.nextDouble(), 2 * Math.PI * random.nextDouble());
            double cosB = (random.nextBoolean() ? 1 : -1) * (0.02 + 0.98 * random.nextDouble());
            double[] b = direction(cosB, 2 * Math.PI * random.nextDouble());
            bsdf.evaluate(m, s, a[0], a[1], a[2], b[0], b[1], b[2], forth);
            if (cosB > 0) {
                bsdf.evaluate(m, s, b[0], b[1], b[2], a[0], a[1], a[2], back);
                assertEquals(forth.r, back.r, 1e-9 * Math.max(1, forth.r), "reflection");
            } else {
                bsdf.evaluate(m, turned, b[0], b[1], b[2], a[0], a[1], a[2], back);
                assertEquals(forth.r * here, back.r * there, 1e-9 * Math.max(1, forth.r * here), "transmission");
            }
        }
    }

    /**
     * The white furnace: a white surface's samples never weigh more than 1, and their mean (a direction
     * not drawn counts 0) is at most 1; it is 1 where no microfacet lobe loses light to masking (a
     * diffuse or delta surface).
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void aWhiteSurfaceGivesBackNoMoreThanItReceives(Case c) {
        Materials m = materials(c, 1);
        Bsdf bsdf = m.bsdf(0);
        Surface s = surface(c);
        double[] wo = direction(c.cosOut(), 0.7);
        BsdfSample out = new BsdfSample();
        SplittableRandom random = new SplittableRandom(5);
        double sum = 0, sum2 = 0;
        for (int i = 0; i < SAMPLES; i++) {
            double w = bsdf.sample(m, s, wo[0], wo[1], wo[2], random.nextDouble(), random.nextDouble(),
                    random.nextDouble(), out) ? out.weightR : 0;
            if (!(w >= 0 && w <= 1 + 1e-12)) {
                fail("a white surface's weight is at most 1: " + w + ", " + c);
            }
            sum += w;
            sum2 += w * w;
        }
        double mean = sum / SAMPLES, error = Math.sqrt(Math.max(0, sum2 / SAMPLES - mean * mean) / SAMPLES);
        assertTrue(mean <= 1 + 4 * error + 1e-12, "mean weight " + mean);
        int lobes = m.lobes(0);
        if (lobes != 0 && (lobes & (Lobe.GLOSSY_REFLECTION | Lobe.GLOSSY_TRANSMISSION)) == 0) {
            assertEquals(1, mean, 4 * error + 1e-12, "nothing is lost: " + c);
        }
    }

    /** Light of its own, finite and not negative, where it {@link Bsdf#emits}; none where it does not. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void aSurfaceSendsLightOfItsOwnOnlyWhereItSaysItEmits(Case c) {
        Materials m = materials(c, 0.8);
        Rgb out = new Rgb();
        out.set(-1, -1, -1);
        m.bsdf(0).emitted(m, surface(c), out);
        if (m.emits(0)) {
            assertTrue(out.r >= 0 && out.g >= 0 && out.b >= 0 && Double.isFinite(out.r + out.g + out.b),
                    "emitted " + out.r + ", " + out.g + ", " + out.b);
        } else {
            assertTrue(out.r == 0 && out.g == 0 && out.b == 0, "a surface that does not emit sends nothing");
        }
    }

    private static double[] unit(double x, double y, double z) {
        double l = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / l, y / l, z / l};
    }
}
