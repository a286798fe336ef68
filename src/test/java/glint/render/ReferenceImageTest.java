package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.image.FrameBuffer;
import glint.image.PfmReader;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import glint.study.RelativeMse;
import java.nio.file.Path;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Glint against images of an independent physically based renderer (src/test/resources/reference,
 * see its README): rendered at the stated settings with the shipped defaults otherwise, the relative
 * MSE must stay within the stated bound.
 */
class ReferenceImageTest {

    @ParameterizedTest
    @CsvSource({"three-spheres, 2.0e-5", "hall-of-mirrors, 6.0e-5"})
    void matchesTheReferenceWithinTheBound(String name, double bound) throws Exception {
        Path folder = Path.of("src/test/resources/reference");
        Scene scene = SceneLoader.load(folder.resolve(name + ".yaml"));
        FrameBuffer reference = PfmReader.read(folder.resolve(name + ".pfm"));
        assertEquals(400, reference.width());
        assertEquals(300, reference.height());
        Config defaults = Config.defaults();
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, 5, defaults.minWeight(), defaults.epsilon());
        FrameBuffer frame = new FrameBuffer(400, 300);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(RenderScene.compile(scene, settings), frame, 16, 0, defaults.screenDivider());
        }
        double relmse = RelativeMse.of(frame, reference);
        System.out.printf("reference %s: relmse %.3e (bound %.1e)%n", name, relmse, bound);
        assertTrue(relmse <= bound, name + ": relmse " + relmse + " exceeds " + bound);
    }
}
