package glint.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.math.Vector3d;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The GGX conductor where its numbers are extreme: views and lights down to the smallest positive
 * cosine, roughness down to the delta mirror's threshold, and seeded random directions. Local
 * frame: the normal is +z.
 */
class GgxGrazingTest {

    /** Cosines to the normal from straight on to the smallest positive double. */
    static final double[] COSINES = {1, 0.5, 0.1, 1e-2, 1e-4, 1e-8, 1e-16, 1e-100, 1e-200, 1e-300,
            Double.MIN_NORMAL, 1e-310, Double.MIN_VALUE};
    /** Roughness from just above the delta mirror (alpha = roughness^2 >= MIRROR_ALPHA) to 1. */
    static final double[] ROUGHNESS = {Math.sqrt(Microfacet.MIRROR_ALPHA) * (1 + 1e-12), 0.04, 0.1, 0.3, 0.5, 1};

    private final Conductor conductor = new Conductor();

    @Test
    void aWhiteConductorsWeightsAreFiniteAndAtMostOneAtEveryGrazingAngle() {
        BsdfSample out = new BsdfSample();
        for (double roughness : ROUGHNESS) {
            Materials m = white(roughness);
            assertFalse(Lobe.allDelta(conductor.lobes(m, 0)), "roughness " + roughness + " has a lobe");
            for (double cos : COSINES) {
                Surface s = surface(cos);
                int sampled = 0;
                for (int i = 0; i < 32; i++) {
                    for (int j = 0; j < 32; j++) {
                        if (!conductor.sample(m, s, sin(cos), 0, cos, (i + 0.5) / 32, (j + 0.5) / 32, 0.5, out)) {
                            continue;
                        }
                        sampled++;
                        String at = "roughness " + roughness + ", cos " + cos + ", u (" + i + ", " + j + ")";
                        assertTrue(out.weightR >= 0 && out.weightR <= 1, "weight " + out.weightR + " at " + at);
                        assertTrue(out.pdf > 0 && Double.isFinite(out.pdf), "pdf " + out.pdf + " at " + at);
                        assertTrue(out.wiZ > 0, "wi below the surface at " + at);
                        assertEquals(1, Math.sqrt(out.wiX * out.wiX + out.wiY * out.wiY + out.wiZ * out.wiZ), 1e-12);
                    }
                }
                // at least a quarter of the visible normals reflect wo above the horizon (half of them at
                // roughness 1 seen straight on, the fewest): the checks above saw real samples
                assertTrue(sampled >= 32 * 32 / 4, sampled + " samples at roughness " + roughness + ", cos " + cos);
            }
        }
    }

    @Test
    void theLobeIsFiniteForEveryPairOfCosinesWhileOneIsAtLeast1eMinus300() {
        Rgb f = new Rgb();
        for (double roughness : ROUGHNESS) {
            Materials m = white(roughness);
            double alpha = Microfacet.alpha(roughness);
            for (double cosOut : COSINES) {
                for (double cosIn : COSINES) {
                    if (cosOut < 1e-300 && cosIn < 1e-300) {
                        continue;
                    }
                    for (double azimuth : new double[] {0, 0.5 * Math.PI, Math.PI}) {
                        Surface s = surface(cosOut);
                        double wiX = -sin(cosIn) * Math.cos(azimuth), wiY = -sin(cosIn) * Math.sin(azimuth);
                        conductor.evaluate(m, s, sin(cosOut), 0, cosOut, wiX, wiY, cosIn, f);
                        double pdf = conductor.pdf(m, s, sin(cosOut), 0, cosOut, wiX, wiY, cosIn);
                        String at = "roughness " + roughness + ", cos out " + cosOut + ", in " + cosIn + ", azimuth "
                                + azimuth;
                        assertTrue(f.r >= 0 && Double.isFinite(f.r), "f " + f.r + " at " + at);
                        assertTrue(f.r * cosIn <= Optics.ggx(1, alpha) / (2 * alpha) * (1 + 1e-12),
                                "f cos " + f.r * cosIn + " above D(n) / (2 alpha) at " + at);
                        assertTrue(pdf >= 0 && Double.isFinite(pdf), "pdf " + pdf + " at " + at);
                    }
                }
            }
        }
    }

    @Test
    void smithsMaskingStaysInItsRangeForSubnormalCosines() {
        for (double alpha : new double[] {Microfacet.MIRROR_ALPHA, 0.1, 1}) {
            for (double cos : new double[] {Double.MIN_NORMAL, 1e-310, Double.MIN_VALUE}) {
                double g1 = Microfacet.g1(cos, alpha), g2 = Microfacet.g2(cos, cos, alpha);
                assertTrue(g1 > 0 && g1 < 1e-300, "G1 " + g1 + " at alpha " + alpha + ", cos " + cos);
                assertTrue(g2 > 0 && g2 <= g1, "G2 " + g2 + " at alpha " + alpha + ", cos " + cos);
            }
        }
    }

    @Test
    void seededRandomDirectionsGiveNoNaNFromAnyBsdf() {
        Random random = new Random(40);
        Bsdf[] bsdfs = {new Lambert(), conductor, new Dielectric()};
        BsdfSample out = new BsdfSample();
        Rgb f = new Rgb();
        for (int n = 0; n < 200_000; n++) {
            Bsdf bsdf = bsdfs[n % 3];
            // roughness log-uniform over [sqrt(MIRROR_ALPHA) / 2, 1]: both sides of the delta mirror
            double roughness = Math.exp(Math.log(Math.sqrt(Microfacet.MIRROR_ALPHA) / 2) * random.nextDouble());
            Vector3d color = new Vector3d(random.nextDouble(), random.nextDouble(), random.nextDouble());
            double ior = 1 + 2 * random.nextDouble();
            double[] numbers = bsdf instanceof Dielectric ? Dielectric.parameters(ior, roughness)
                    : Conductor.parameters(roughness);
            Materials m = Materials.of(List.of(new Materials.Material(bsdf, new MetalResponse(), color, 0, 0, 0, 0,
                    ior, numbers)));
            // cosines log-uniform down to 1e-300, half of them grazing below 1e-3
            double cosOut = Math.pow(10, -300 * Math.pow(random.nextDouble(), 6));
            Surface s = surface(cosOut);
            s.front = random.nextBoolean();
            double woX = sin(cosOut);
            String at = bsdf.getClass().getSimpleName() + ", roughness " + roughness + ", cos " + cosOut;
            if (bsdf.sample(m, s, woX, 0, cosOut, random.nextDouble(), random.nextDouble(), random.nextDouble(), out)) {
                assertTrue(Double.isFinite(out.wiX + out.wiY + out.wiZ), "wi at " + at);
                assertTrue(out.weightR >= 0 && out.weightG >= 0 && out.weightB >= 0
                        && Math.max(out.weightR, Math.max(out.weightG, out.weightB)) <= 1, "weight at " + at);
                assertTrue(out.pdf >= 0 && Double.isFinite(out.pdf), "pdf " + out.pdf + " at " + at);
            }
            double cosIn = Math.pow(10, -300 * Math.pow(random.nextDouble(), 6));
            double phi = 2 * Math.PI * random.nextDouble();
            double wiX = sin(cosIn) * Math.cos(phi), wiY = sin(cosIn) * Math.sin(phi);
            bsdf.evaluate(m, s, woX, 0, cosOut, wiX, wiY, cosIn, f);
            assertTrue(f.r >= 0 && f.g >= 0 && f.b >= 0 && Double.isFinite(f.r + f.g + f.b), "f at " + at);
            double pdf = bsdf.pdf(m, s, woX, 0, cosOut, wiX, wiY, cosIn);
            assertTrue(pdf >= 0 && Double.isFinite(pdf), "pdf at " + at);
        }
    }

    private static Materials white(double roughness) {
        return Materials.of(List.of(new Materials.Material(new Conductor(), new MetalResponse(),
                new Vector3d(1, 1, 1), 0, 0, 0, 0, 1.5, Conductor.parameters(roughness))));
    }

    /** A surface with normal +z, seen from a direction at cosine {@code cos}. */
    private static Surface surface(double cos) {
        Surface s = new Surface();
        s.nz = 1;
        s.cosIncident = cos;
        s.front = true;
        return s;
    }

    private static double sin(double cos) {
        return Math.sqrt(Math.max(0, 1 - cos * cos));
    }
}
