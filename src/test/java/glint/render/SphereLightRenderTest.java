package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import glint.math.Vector3d;
import glint.scene.Scene;
import glint.study.RelativeMse;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Lights with a size in both integrators: a sphere light shrunk to 1e-4 renders as its point light;
 * the converged direct light of a sphere light and of a sun on a matte plane is the irradiance
 * worked out by hand; Whitted's direct light (light samples alone) and the path integrator's (light
 * and BSDF samples weighed by the power heuristic) converge to the same image.
 */
class SphereLightRenderTest {

    /** A floor, a matte ball and a rough metal ball under a light above and behind the camera's view. */
    private static final String BALLS = """
            camera: {position: [0, 2.5, -4], look_at: [0, 0.5, 0.5], fov: 50}
            lights:
              - {type: point, position: [1.5, 3, 0.5], intensity: 12, RADIUS}
            objects:
              - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.7, 0.7, 0.7]}}
              - {type: sphere, center: [-0.7, 0.5, 0.3], radius: 0.5, material: {type: matte, color: [0.8, 0.3, 0.2]}}
              - {type: sphere, center: [0.7, 0.5, 0.6], radius: 0.5, material: {type: metal, color: [0.9, 0.8, 0.6], roughness: 0.4}}
            """;

    @ParameterizedTest
    @EnumSource(names = {"WHITTED", "PATH"}) // bdpt: BdptIntegratorTest, statistically
    void aSphereLightOfRadius1eMinus4RendersAsItsPointLight(LightTransport transport) {
        FrameBuffer point = render(BALLS.replace(", RADIUS", ""), transport, 16, 3);
        FrameBuffer tiny = render(BALLS.replace("RADIUS", "radius: 1e-4"), transport, 16, 3);
        double relMse = RelativeMse.of(tiny, point);
        assertTrue(relMse < 1e-3, transport + ": relMSE " + relMse);
    }

    /**
     * A sphere light wholly above a matte plane gives it the irradiance of its point light exactly,
     * c I cos / d^2 (a uniform sphere's field outside it is its centre's), so the converged pixel is
     * albedo / pi times that, in both integrators.
     */
    @ParameterizedTest
    @EnumSource(names = {"WHITTED", "PATH"}) // bdpt: BdptIntegratorTest, statistically
    void aSphereLightsDirectLightOnAPlaneIsTheIrradianceOfItsPointLight(LightTransport transport) {
        String yaml = """
                camera: {position: [0, 1, 0], look_at: [0, 0, 4], fov: 30}
                lights:
                  - {type: point, position: [0.5, 2, 4], radius: 0.8, intensity: 10}
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.5, 0.5, 0.5]}}
                """;
        int w = 32, h = 24;
        FrameBuffer frame = render(yaml, transport, 256, 1, w, h);
        PinholeCamera camera = new PinholeCamera(Renders.scene(yaml).camera());
        int checked = 0;
        for (int y = h / 2 + 2; y < h; y += 3) {
            for (int x = 2; x < w; x += 5) {
                Vector3d d = camera.direction(x + 0.5, y + 0.5, w, h);
                double t = 1 / -d.y();
                double px = t * d.x(), pz = t * d.z();
                double lx = 0.5 - px, ly = 2, lz = 4 - pz;
                double d2 = lx * lx + ly * ly + lz * lz;
                double expected = 0.5 / Math.PI * 10 * (ly / Math.sqrt(d2)) / d2;
                assertEquals(expected, frame.get(x, y, 0), 0.01 * expected, transport + " at pixel " + x + ", " + y);
                checked++;
            }
        }
        assertTrue(checked > 10);
    }

    /** A sun of any size straight above a matte plane gives it the irradiance c I: the pixel is albedo / pi c I. */
    @ParameterizedTest
    @EnumSource(LightTransport.class)
    void aSunsDirectLightOnAPlaneFacingItIsItsIrradiance(LightTransport transport) {
        String yaml = """
                camera: {position: [0, 1, 0], look_at: [0, 0, 4], fov: 30}
                lights:
                  - {type: directional, direction: [0, -1, 0], angle: 40, intensity: 3}
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.5, 0.5, 0.5]}}
                """;
        FrameBuffer frame = render(yaml, transport, 256, 1, 16, 12);
        for (int x = 0; x < 16; x++) {
            assertEquals(0.5 / Math.PI * 3, frame.get(x, 10, 0), 0.01 * 0.5 / Math.PI * 3, transport + " at " + x);
        }
    }

    /**
     * Whitted's direct light from a sphere light half hidden by a ball (light samples only, stratified
     * over the pixel's samples) and the path integrator's at depth 1 (light and BSDF samples weighed by
     * the power heuristic) are two estimates of the same integral: the images agree.
     */
    @Test
    void whittedsDirectLightIsThePathIntegratorsAtDepthOne() {
        String yaml = BALLS.replace("RADIUS", "radius: 0.6");
        FrameBuffer whitted = render(yaml, LightTransport.WHITTED, 256, 1);
        FrameBuffer path = render(yaml, LightTransport.PATH, 256, 1);
        double relMse = RelativeMse.of(whitted, path);
        assertTrue(relMse < 2e-3, "relMSE " + relMse);
    }

    private static FrameBuffer render(String yaml, LightTransport transport, int samples, int depth) {
        return render(yaml, transport, samples, depth, 48, 36);
    }

    private static FrameBuffer render(String yaml, LightTransport transport, int samples, int depth, int w, int h) {
        Scene scene = Renders.scene(yaml);
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, depth, 0, Renders.EPSILON)
                .withTransport(transport);
        FrameBuffer frame = new FrameBuffer(w, h);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(RenderScene.compile(scene, settings), frame, samples, 0, 4);
        }
        return frame;
    }
}
