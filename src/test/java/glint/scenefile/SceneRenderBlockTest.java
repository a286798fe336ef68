package glint.scenefile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import glint.input.InputException;
import glint.scene.Camera;
import glint.scene.RenderBlock;
import glint.scene.Scene;
import org.junit.jupiter.api.Test;

/** The scene key {@code render:}: how a scene is meant to be seen, and what is wrong with a bad block. */
class SceneRenderBlockTest {

    private static final String FILE = "scenes/r.yaml";

    private static String error(String text) {
        return assertThrows(InputException.class, () -> SceneLoader.parse(FILE, text)).getMessage();
    }

    @Test
    void everyKeyIsRead() throws InputException {
        RenderBlock r = SceneLoader.parse(FILE, """
                render:
                  shading: phong
                  samples: 16
                  noise: 0.02
                  max_samples: 512
                  recursion_max: 8
                  min_weight: 0.001
                  width: 640
                  height: 360
                """).render();
        assertEquals("phong", r.shading());
        assertEquals(16, r.samples());
        assertEquals(0.02, r.noise());
        assertEquals(512, r.maxSamples());
        assertEquals(8, r.recursionMax());
        assertEquals(0.001, r.minWeight());
        assertEquals(640, r.width());
        assertEquals(360, r.height());
        assertEquals(new RenderBlock.Place(3, 12), r.place("samples"));
    }

    @Test
    void noBlockOrAnEmptyOneSetsNothing() throws InputException {
        assertSame(RenderBlock.NONE, SceneLoader.parse(FILE, "ambient: [0, 0, 0]\n").render());
        assertSame(RenderBlock.NONE, SceneLoader.parse(FILE, "render:\n").render());
        RenderBlock some = SceneLoader.parse(FILE, "render: {samples: 9}\n").render();
        assertNull(some.shading());
        assertNull(some.width());
        assertEquals(9, some.samples());
    }

    @Test
    void theBlockSurvivesACameraChange() throws InputException {
        Scene s = SceneLoader.parse(FILE, "render: {shading: phong}\n");
        assertEquals("phong", s.withCamera(Camera.defaults()).render().shading());
    }

    @Test
    void badKeysAndValuesArePositionedErrors() {
        assertEquals("scenes/r.yaml:1:10: unknown key 'shadng' in render (did you mean 'shading'?)",
                error("render: {shadng: phong}\n"));
        assertEquals("scenes/r.yaml:2:12: unknown shading model 'phon' (did you mean 'phong'?)",
                error("render:\n  shading: phon\n"));
        assertEquals("scenes/r.yaml:1:19: samples must be a perfect square (1, 4, 9, 16, ...), got 8",
                error("render: {samples: 8}\n"));
        assertEquals("scenes/r.yaml:1:19: samples must be a whole number from 1 to 4096, got 0",
                error("render: {samples: 0}\n"));
        assertEquals("scenes/r.yaml:1:25: recursion_max must be a whole number from 1 to 64, got 2.5",
                error("render: {recursion_max: 2.5}\n"));
        assertEquals("scenes/r.yaml:1:17: noise must be 0 (off) or a number from 0.0001 to 1, got 5",
                error("render: {noise: 5}\n"));
        assertEquals("scenes/r.yaml:1:17: noise must be 0 (off) or a number from 0.0001 to 1, got 1e-5",
                error("render: {noise: 1e-5}\n"));
        assertEquals("scenes/r.yaml:1:23: max_samples must be a whole number from 1 to 65536, got 0",
                error("render: {max_samples: 0}\n"));
        assertEquals("scenes/r.yaml:1:22: min_weight must lie in [0, 1], got 2",
                error("render: {min_weight: 2}\n"));
        assertEquals("scenes/r.yaml:1:17: expected a number for width, got the quoted string '640'",
                error("render: {width: \"640\", height: 360}\n"));
        assertEquals("scenes/r.yaml:1:9: the still size needs both width and height in render",
                error("render: {width: 640}\n"));
        assertEquals("scenes/r.yaml:1:9: expected a mapping for render, got 'phong'",
                error("render: phong\n"));
        assertEquals("scenes/r.yaml:1:22: duplicate key 'samples' in render",
                error("render: {samples: 4, samples: 9}\n"));
    }
}
