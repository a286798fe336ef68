package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;

import glint.image.FrameBuffer;
import org.junit.jupiter.api.Test;

/**
 * The phong model's values worked out by hand (docs/conventions.md, "phong"): its light term is E / pi, as
 * Lambert's, and a metal's highlight and reflection take its colour, where other types' stay white.
 */
class PhongRadianceTest {

    /** A light straight behind the eye on a sphere seen head-on: n.l = 1 and r.v = 1 at the centre pixel. */
    private static final String HEAD_ON = """
            camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 10}
            lights:
              - {type: directional, direction: [0, 0, 1], intensity: 2}
            objects:
              - {type: sphere, center: [0, 0, 5], radius: 1, material: %s}
            """;

    @Test
    void matteIsKdColourTimesEOverPiPlusAWhiteHighlight() {
        FrameBuffer frame = Renders.render(HEAD_ON.formatted(
                "{type: matte, color: [0.8, 0.4, 0.2], kd: 0.5, ks: 0.25, shininess: 10}"), 9, 9, 1, 1, Shading.PHONG);
        double e = 2 / Math.PI;
        double[] color = {0.8, 0.4, 0.2};
        for (int c = 0; c < 3; c++) {
            assertEquals(0.5 * color[c] * e + 0.25 * e, frame.get(4, 4, c), 1e-6, "channel " + c);
        }
    }

    @Test
    void aMetalsHighlightTakesItsColour() {
        FrameBuffer frame = Renders.render(HEAD_ON.formatted(
                "{type: metal, color: [1.0, 0.77, 0.34], kd: 0.1, ks: 0.7, shininess: 50}"), 9, 9, 1, 1, Shading.PHONG);
        double e = 2 / Math.PI;
        double[] gold = {1.0, 0.77, 0.34};
        for (int c = 0; c < 3; c++) {
            assertEquals((0.1 + 0.7) * gold[c] * e, frame.get(4, 4, c), 1e-6, "channel " + c);
        }
    }

    /** A gold mirror in front of a white sky: what it reflects is ks x its colour x the sky, not ks x the sky. */
    @Test
    void aMetalsReflectionTakesItsColourAndGlassStaysWhite() {
        String yaml = """
                camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 10}
                background: [1, 1, 1]
                objects:
                  - {type: sphere, center: [0, 0, 5], radius: 1, material: %s}
                """;
        FrameBuffer gold = Renders.render(yaml.formatted(
                "{type: metal, color: [1.0, 0.77, 0.34], kd: 0, ks: 0.7}"), 9, 9, 1, 2, Shading.PHONG);
        double[] color = {1.0, 0.77, 0.34};
        for (int c = 0; c < 3; c++) {
            assertEquals(0.7 * color[c], gold.get(4, 4, c), 1e-6, "channel " + c);
        }
        FrameBuffer glass = Renders.render(yaml.formatted(
                "{type: glass, color: [1.0, 0.77, 0.34], kd: 0, ks: 0.2, kt: 0}"), 9, 9, 1, 2, Shading.PHONG);
        for (int c = 0; c < 3; c++) {
            assertEquals(0.2, glass.get(4, 4, c), 1e-6, "channel " + c);
        }
    }
}
