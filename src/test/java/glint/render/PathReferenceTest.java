package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.image.FrameBuffer;
import glint.image.PfmReader;
import glint.scenefile.SceneLoader;
import glint.study.ImageErrors;
import glint.study.RelativeMse;
import java.nio.file.Path;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The path integrator against images of an independent path tracer (src/test/resources/reference-pt,
 * see its README): at its stated settings (the reference's size, 256 samples, 1024 for caustic-lamp's small
 * light, depth 64, cook-torrance) the
 * relative MSE and the mean 8-bit error stay within the stated bounds. (The README's third bound,
 * FLIP, is not computed here.)
 */
class PathReferenceTest {

    @ParameterizedTest
    @CsvSource({"bounce-box, 256, 3.3e-4, 1.24", "sky-and-sun, 256, 1.1e-4, 0.55", "lamp-and-frost, 256, 0.041, 8.9",
            "lens, 256, 0.0123, 0.88", "caustic-lamp, 1024, 0.043, 6.8", "sun-disc, 256, 5.89e-5, 0.478",
            "two-lamps, 256, 7.68e-3, 4.93", "frosted-pair, 256, 2.66e-2, 6.42", "near-focus, 256, 2.06e-2, 1.63",
            "brushed-metals, 256, 3.12e-2, 3.20"})
    void matchesThePhysicallyBasedReferenceWithinTheBound(String name, int samples, double relMseBound,
                                                          double levelsBound) throws Exception {
        assertWithinBound(LightTransport.PATH, name, samples, relMseBound, levelsBound);
    }

    /**
     * Renders reference scene {@code name} with {@code transport} at the reference's size, {@code samples}
     * samples, depth 64 and cook-torrance, and asserts its relative MSE and mean 8-bit error within the bounds.
     */
    static void assertWithinBound(LightTransport transport, String name, int samples, double relMseBound,
                                  double levelsBound) throws Exception {
        Path folder = Path.of("src/test/resources/reference-pt");
        FrameBuffer reference = PfmReader.read(folder.resolve(name + ".pfm"));
        int width = reference.width(), height = reference.height(); // 400 x 300, or 200 x 150 (the README)
        assertEquals(width * 3, height * 4);
        Config defaults = Config.defaults();
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, 64, defaults.minWeight(),
                defaults.epsilon()).withTransport(transport);
        FrameBuffer frame = new FrameBuffer(width, height);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(RenderScene.compile(SceneLoader.load(folder.resolve(name + ".yaml")), settings), frame, samples, 0,
                    defaults.screenDivider());
        }
        double relMse = RelativeMse.of(frame, reference);
        double levels = ImageErrors.meanLevels(frame, reference);
        System.out.printf("reference-pt %s, %s: relMSE %.3e (bound %.1e), 8-bit %.3f (bound %.2f)%n", transport.key(),
                name, relMse, relMseBound, levels, levelsBound);
        assertTrue(relMse <= relMseBound, name + ": relMSE " + relMse + " exceeds " + relMseBound);
        assertTrue(levels <= levelsBound, name + ": mean 8-bit error " + levels + " exceeds " + levelsBound);
    }
}
