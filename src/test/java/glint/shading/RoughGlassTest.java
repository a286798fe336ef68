package glint.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.math.Vector3d;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * Rough glass against values worked out by hand (Walter et al. 2007, radiance unscaled): its lobes by
 * roughness and index, f straight through at normal incidence, the smooth glass it tends to as the
 * roughness goes to 0, and Whitted's single rays, which do not depend on the roughness. Local frame:
 * the normal is +z.
 */
class RoughGlassTest {

    private final Dielectric glass = new Dielectric();

    static Materials glass(double ior, double roughness, boolean exactFresnel) {
        return Materials.of(List.of(new Materials.Material(new Dielectric(), new GlassResponse(),
                new Vector3d(1, 0.5, 0.25), 0.01, 0.2, 0.79, 125, ior, Dielectric.parameters(ior, roughness))),
                exactFresnel);
    }

    static Surface up(boolean front, double cos) {
        Surface s = new Surface();
        s.nz = 1;
        s.front = front;
        s.cosIncident = cos;
        return s;
    }

    @Test
    void roughGlassHasGlossyLobesSmoothGlassAndGlassOfIndexOneDeltaOnes() {
        int glossy = Lobe.GLOSSY_REFLECTION | Lobe.GLOSSY_TRANSMISSION;
        int delta = Lobe.SPECULAR_REFLECTION | Lobe.SPECULAR_TRANSMISSION;
        assertEquals(glossy, glass(1.5, 0.25, true).lobes(0));
        assertEquals(glossy, glass(1.5, 1, true).lobes(0));
        assertEquals(delta, glass(1.5, 0, true).lobes(0));
        // alpha = 0.03^2 = 9e-4 is below the mirror threshold 1e-3: smooth
        assertEquals(delta, glass(1.5, 0.03, true).lobes(0));
        // a boundary of index 1 bends nothing: light passes straight through however rough
        assertEquals(delta, glass(1, 0.5, true).lobes(0));
        assertTrue(Lobe.transmitsNonDelta(glass(1.5, 0.25, true).lobes(0)));
        assertTrue(!Lobe.transmitsNonDelta(glass(1.5, 0, true).lobes(0)));
    }

    /**
     * At normal incidence straight through, h = n: D = 1 / (pi alpha^2), G2 = 1 (Lambda(1) = 0), F = F0 =
     * ((1 - ior) / (1 + ior))^2, and f = D (1 - F0) / (eta - 1)^2 times the colour, eta = n_o / n_i.
     */
    @Test
    void fStraightThroughAtNormalIncidenceIsWorkedOutByHand() {
        Rgb f = new Rgb();
        for (boolean front : new boolean[] {true, false}) {
            for (double ior : new double[] {1.5, 2.4, 0.75}) {
                double roughness = 0.5, alpha = roughness * roughness;
                Materials m = glass(ior, roughness, true);
                glass.evaluate(m, up(front, 1), 0, 0, 1, 0, 0, -1, f);
                double eta = front ? 1 / ior : ior, f0 = (1 - ior) * (1 - ior) / ((1 + ior) * (1 + ior));
                double expected = (1 - f0) / (Math.PI * alpha * alpha * (eta - 1) * (eta - 1));
                assertEquals(expected, f.r, 1e-12 * expected, "ior " + ior + (front ? " front" : " back"));
                assertEquals(expected * 0.5, f.g, 1e-12 * expected, "the colour tints the transmitted light");
                // and reflected straight back: D F0 G2 / 4
                glass.evaluate(m, up(front, 1), 0, 0, 1, 0, 0, 1, f);
                assertEquals(f0 / (Math.PI * alpha * alpha) / 4, f.r, 1e-12, "reflected, ior " + ior);
                assertEquals(f.r, f.b, 0, "reflected light is not tinted");
            }
        }
    }

    /**
     * As the roughness falls towards the mirror threshold, the rough glass's samples carry what the
     * smooth one's do: F(cos) of the light reflected, 1 - F(cos) refracted, each within 1 %.
     */
    @Test
    void nearlySmoothRoughGlassReflectsAndRefractsAsSmoothGlassDoes() {
        BsdfSample out = new BsdfSample();
        for (boolean exact : new boolean[] {true, false}) {
            for (double cos : new double[] {0.9, 0.5, 0.2}) {
                for (boolean front : new boolean[] {true, false}) {
                    Materials m = glass(1.5, 0.04, exact); // alpha 1.6e-3
                    Surface s = up(front, cos);
                    double sin = Math.sqrt(1 - cos * cos);
                    SplittableRandom random = new SplittableRandom(13);
                    double reflected = 0, refracted = 0;
                    int n = 50_000;
                    for (int i = 0; i < n; i++) {
                        if (glass.sample(m, s, sin, 0, cos, random.nextDouble(), random.nextDouble(),
                                random.nextDouble(), out)) {
                            if (out.transmitted()) {
                                refracted += out.weightR;
                            } else {
                                reflected += out.weightR;
                            }
                        }
                    }
                    double eta = front ? 1 / 1.5 : 1.5;
                    double fresnel = exact ? Optics.fresnelDielectric(cos, eta) : Optics.schlickDielectric(cos, eta);
                    String at = "cos " + cos + (front ? " front" : " back") + (exact ? " exact" : " Schlick");
                    assertEquals(fresnel, reflected / n, 0.01, at);
                    assertEquals(1 - fresnel, refracted / n, 0.01, at);
                }
            }
        }
    }

    @Test
    void whittedsSingleRaysDoNotDependOnTheRoughness() {
        GlassResponse response = new GlassResponse();
        SingleRays smooth = new SingleRays(), rough = new SingleRays();
        for (boolean front : new boolean[] {true, false}) {
            for (double cos : new double[] {1, 0.6, 0.1}) {
                response.specular(glass(1.5, 0, true), up(front, cos), smooth);
                response.specular(glass(1.5, 0.5, true), up(front, cos), rough);
                assertEquals(smooth.eta, rough.eta);
                assertEquals(smooth.reflectR, rough.reflectR);
                assertEquals(smooth.transmitG, rough.transmitG);
            }
        }
    }
}
