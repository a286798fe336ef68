package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import glint.input.InputException;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Shading;
import glint.render.Tracer;
import glint.scenefile.SceneLoader;
import org.junit.jupiter.api.Test;

/**
 * The cook-torrance highlight at grazing light and view and at roughness 0 or nearly 0: finite values,
 * and a lobe that reflects at most the light it receives (directional albedo <= 1 with Fresnel = 1).
 */
class CookTorranceStabilityTest {

    @Test
    void glintsLobeIsFiniteEverywhereTheTextbookOneIsNot() {
        for (double r : Stability.LOBE_ROUGHNESS) {
            int[] bad = Microfacet.nonFinite(Stability.LOBE_ANGLES, r);
            assertEquals(0, bad[0], "Glint's lobe at roughness " + r);
        }
        // Beckmann at m = 0 divides 0 by 0; at m = 1e-160, m^2 is subnormal and 1 / (pi m^2) overflows
        assertTrue(Microfacet.nonFinite(Stability.LOBE_ANGLES, 0)[1] > 0);
        assertTrue(Microfacet.nonFinite(Stability.LOBE_ANGLES, 1e-160)[1] > 0);
    }

    @Test
    void albedoAtRoughnessOneMatchesItsClosedForm() {
        // alpha = 1: D = 1/pi and V = 1 / (2 (n.l + n.v)); at normal view E = int_0^1 mu / (1 + mu) dmu = 1 - ln 2
        assertEquals(1 - Math.log(2), Microfacet.glintAlbedo(1, 1, 256), 2e-3);
    }

    @Test
    void albedoNeverExceedsOneAtAnyRoughnessOrViewAngle() {
        for (double r : new double[] {1e-6, 1e-3, 0.05, 0.2, 0.5, 1}) {
            for (double viewDegrees : new double[] {0, 45, 80, 89, 89.99}) {
                double e = Microfacet.glintAlbedo(Math.cos(Math.toRadians(viewDegrees)), r, 128);
                assertTrue(Double.isFinite(e) && e >= 0 && e <= 1 + 1e-3,
                        "albedo " + e + " at roughness " + r + ", view " + viewDegrees);
            }
        }
        // a near-mirror lobe reflects (almost) everything from a view that is not grazing
        assertEquals(1, Microfacet.glintAlbedo(Math.cos(Math.toRadians(45)), 1e-3, 128), 1e-3);
    }

    @Test
    void metalSpheresUnderGrazingLightsRenderFiniteAtEveryRoughness() throws InputException {
        // lights skimming the spheres' limbs and the floor, the camera low over the floor
        for (double roughness : new double[] {0, 1e-6, 1e-4, 1e-2, 0.3, 1}) {
            String yaml = """
                    camera: {position: [0, 0.05, -6], look_at: [0, 0.5, 0], fov: 70}
                    lights:
                      - {type: directional, direction: [1, -0.0001, 0], intensity: 3}
                      - {type: directional, direction: [0, -1e-9, -1], intensity: 3}
                      - {type: point, position: [0, 1e-7, 3], intensity: 50}
                    objects:
                      - {type: sphere, center: [-1.1, 1, 0], radius: 1, material: {type: metal, roughness: %s}}
                      - {type: sphere, center: [1.1, 1, 0], radius: 1, material: {type: metal, roughness: %s, color: [1, 0.8, 0.4]}}
                      - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: metal, roughness: %s}}
                    """.formatted(roughness, roughness, roughness);
            RenderScene scene = RenderScene.compile(SceneLoader.parse("grazing.yaml", yaml),
                    new RenderSettings(Shading.COOK_TORRANCE, 4, 0, 1e-9));
            FrameBuffer frame = new FrameBuffer(64, 48);
            try (Tracer tracer = new Tracer(2)) {
                tracer.render(scene, frame, 4, 0, 4);
            }
            for (float v : frame.rgb()) {
                assertTrue(Float.isFinite(v) && v >= 0, "radiance " + v + " at roughness " + roughness);
            }
        }
    }
}
