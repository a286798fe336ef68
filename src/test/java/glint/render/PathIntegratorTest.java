package glint.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import glint.math.Vector3d;
import glint.scene.Scene;
import glint.shading.Conductor;
import glint.shading.Materials;
import glint.shading.MetalResponse;
import glint.shading.Rgb;
import glint.shading.Surface;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The path integrator's invariants: a furnace (a white surface under a uniform sky), its first vertex
 * equal to Whitted's direct light, the same bytes at any thread and tile count, and nothing but
 * finite values in the frame.
 */
class PathIntegratorTest {

    static FrameBuffer renderPath(Scene scene, int width, int height, int samples, int depth, int threads,
                                  int divider) {
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, depth, 0.01, Renders.EPSILON)
                .withTransport(LightTransport.PATH);
        FrameBuffer frame = new FrameBuffer(width, height);
        try (Tracer tracer = new Tracer(threads)) {
            tracer.render(RenderScene.compile(scene, settings), frame, samples, 0, divider);
        }
        return frame;
    }

    @Test
    void aWhiteMatteSphereUnderASkyOfRadianceOneIsOneEverywhere() {
        Scene scene = Renders.scene("""
                camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 40}
                background: [1, 1, 1]
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: {type: matte, color: [1, 1, 1]}}
                """);
        float[] rgb = renderPath(scene, 24, 18, 16, 64, 2, 3).rgb();
        for (float v : rgb) {
            assertEquals(1, v, 1e-6); // every path leaves the convex sphere once, at weight 1
        }
    }

    @Test
    void aWhiteRoughMetalUnderASkyLosesOnlyWhatItsSingleScatteringLoses() {
        double roughness = 0.7;
        Scene scene = Renders.scene("""
                camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 1}
                background: [1, 1, 1]
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: {type: metal, color: [1, 1, 1], roughness: 0.7}}
                """);
        FrameBuffer frame = renderPath(scene, 4, 4, 1024, 64, 2, 2);
        double sum = 0, sum2 = 0;
        float[] rgb = frame.rgb();
        for (int i = 0; i < rgb.length; i += 3) {
            sum += rgb[i];
            sum2 += rgb[i] * rgb[i];
        }
        int pixels = rgb.length / 3;
        double mean = sum / pixels;
        // the directional albedo at normal view, by quadrature of f cos over the hemisphere
        Materials m = Materials.of(List.of(new Materials.Material(new Conductor(), new MetalResponse(),
                Vector3d.ONE, 1, 0, 0, 1, 1.5, Conductor.parameters(roughness))));
        Surface s = new Surface();
        s.nz = 1;
        s.cosIncident = 1;
        s.front = true;
        Rgb f = new Rgb();
        double albedo = 0;
        int nu = 2000, nPhi = 64;
        for (int i = 0; i < nu; i++) {
            double z = (i + 0.5) / nu, r = Math.sqrt(1 - z * z);
            for (int j = 0; j < nPhi; j++) {
                double phi = (j + 0.5) / nPhi * 2 * Math.PI;
                new Conductor().evaluate(m, s, 0, 0, 1, r * Math.cos(phi), r * Math.sin(phi), z, f);
                albedo += f.r * z;
            }
        }
        albedo *= 2 * Math.PI / (nu * nPhi);
        // at alpha 0.49 a fifth of the facets seen face-on mirror below the horizon (1 / (1 + alpha^2) lie within 45 degrees)
        assertTrue(albedo < 0.85 && albedo > 0.5, "a rough conductor loses light it would scatter more than once: " + albedo);
        // each pixel averages 1024 stratified samples: their spread bounds the mean's error from above
        double spread = Math.sqrt(Math.max(0, sum2 / pixels - mean * mean));
        assertEquals(albedo, mean, 0.01 + 4 * spread / Math.sqrt(pixels));
    }

    /**
     * White rough glass under a sky of radiance 1: every path leaves it at last, weighed by G2 / G1 <= 1 at
     * each crossing or reflection, so no pixel is brighter than the sky, and the light lost to single
     * scattering is small (the image's mean, the sky around the ball included, measured 0.979).
     */
    @Test
    void aWhiteRoughGlassUnderASkyGivesBackAtMostTheSky() {
        Scene scene = Renders.scene("""
                camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 30}
                background: [1, 1, 1]
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: {type: glass, roughness: 0.25}}
                """);
        float[] rgb = renderPath(scene, 12, 12, 64, 64, 2, 3).rgb();
        double sum = 0;
        for (float v : rgb) {
            assertTrue(v <= 1 + 1e-6, "no brighter than the sky: " + v);
            sum += v;
        }
        double mean = sum / rgb.length;
        assertTrue(mean > 0.9, "the mean " + mean);
    }

    @Test
    void theFirstVertexIsWhittedsDirectLight() {
        Random random = new Random(40);
        for (int i = 0; i < 12; i++) {
            Scene scene = Renders.scene(RandomScenes.upToSixSpheres(random));
            FrameBuffer whitted = Renders.render(scene, 40, 30, 1, 1, Shading.COOK_TORRANCE, 2, 3);
            FrameBuffer path = renderPath(scene, 40, 30, 1, 1, 2, 3);
            float[] w = whitted.rgb(), p = path.rgb();
            for (int k = 0; k < w.length; k++) {
                assertEquals(w[k], p[k], 1e-6 * Math.max(1, w[k]), "scene " + i + ", value " + k);
            }
        }
    }

    @Test
    void theImageIsTheSameBytesAtAnyThreadAndTileCount() {
        Random random = new Random(7);
        for (int i = 0; i < 3; i++) {
            Scene scene = Renders.scene(RandomScenes.upToSixSpheres(random));
            float[] one = renderPath(scene, 33, 21, 4, 8, 1, 1).rgb();
            assertArrayEquals(one, renderPath(scene, 33, 21, 4, 8, 2, 8).rgb());
            assertArrayEquals(one, renderPath(scene, 33, 21, 4, 8, 2, 13).rgb());
        }
    }

    @Test
    void everyValueIsFiniteOnRandomScenes() {
        Random random = new Random(11);
        for (int i = 0; i < 10; i++) {
            Scene scene = Renders.scene(RandomScenes.upToSixSpheres(random) + "background: [0.4, 0.5, 0.9]\n");
            for (float v : renderPath(scene, 32, 24, 4, 32, 2, 4).rgb()) {
                assertTrue(Float.isFinite(v) && v >= 0, "a finite, non-negative radiance: " + v);
            }
        }
    }
}
