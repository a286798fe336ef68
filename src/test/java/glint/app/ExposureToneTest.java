package glint.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.config.ConfigLoader;
import glint.config.Flags;
import glint.image.ViewTransform;
import glint.image.ViewTransform.Tone;
import glint.scene.RenderBlock;
import glint.scenefile.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The view transform's settings: config keys exposure and tone, the render: block's keys of the same names and
 * the flags --exposure and --tone, ranked as every setting; bad values refused in words; a PFM never changed.
 */
class ExposureToneTest {

    private static final String SCENE = """
            camera: {position: [0, 1, -4], look_at: [0, 1, 0]}
            lights:
              - {type: point, position: [-3, 5, -4], intensity: 80}
            objects:
              - {type: sphere, center: [0, 1, 0], radius: 1, material: {type: matte, color: [1, 0.77, 0.34]}}
              - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
            """;

    @TempDir
    Path dir;

    private record Result(int status, String out, String err) {
    }

    private static Result run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = Main.run(args, new PrintWriter(out, true), new PrintWriter(err, true));
        return new Result(status, out.toString(), err.toString());
    }

    private Path still(String name, String... flags) throws IOException {
        Path scene = Files.writeString(dir.resolve("scene.yaml"), SCENE);
        Path config = Files.writeString(dir.resolve("c.properties"), "display_width=32\ndisplay_height=24\nsamples=1\n");
        Path out = dir.resolve(name);
        String[] args = new String[flags.length + 6];
        System.arraycopy(new String[] {"--scene", scene.toString(), "--config", config.toString(), "--output",
                out.toString()}, 0, args, 0, 6);
        System.arraycopy(flags, 0, args, 6, flags.length);
        Result r = run(args);
        assertEquals(0, r.status(), r::err);
        return out;
    }

    @Test
    void aPfmHoldsTheSameLinearBytesWhateverTheExposureAndTone() throws IOException {
        byte[] plain = Files.readAllBytes(still("plain.pfm"));
        assertArrayEquals(plain, Files.readAllBytes(still("bright.pfm", "--exposure", "3", "--tone", "standard")));
        assertArrayEquals(plain, Files.readAllBytes(still("dark.pfm", "--exposure", "-2.5", "--tone", "neutral")));
        BufferedImage png = ImageIO.read(still("plain.png").toFile());
        BufferedImage brighter = ImageIO.read(still("brighter.png", "--exposure", "2").toFile());
        assertTrue((brighter.getRGB(16, 12) & 0xff) > (png.getRGB(16, 12) & 0xff), "two stops brighter");
    }

    @Test
    void theConfigTheBlockAndTheFlagRankAsEverySetting() throws Exception {
        Config config = ConfigLoader.parse("c.properties", "exposure=1\ntone=standard\n");
        assertEquals(new ViewTransform(1, Tone.STANDARD), config.view());
        RenderBlock block = SceneLoader.parse("s.yaml", SCENE + "render: {exposure: -0.5, tone: neutral}\n").render();
        assertEquals(-0.5, block.exposure());
        assertEquals("neutral", block.tone());
        assertEquals(new ViewTransform(-0.5, Tone.NEUTRAL), Flags.NONE.effective(config, block).view());
        RenderBlock exposureOnly = SceneLoader.parse("s.yaml", SCENE + "render: {exposure: 2}\n").render();
        assertEquals(new ViewTransform(2, Tone.STANDARD), Flags.NONE.effective(config, exposureOnly).view());
        Flags flags = new Flags(null, null, null, null, null, null, null, 3.0, "standard");
        assertEquals(new ViewTransform(3, Tone.STANDARD), flags.effective(config, block).view());
        Flags toneOnly = new Flags(null, null, null, null, null, null, null, null, "neutral");
        assertEquals(new ViewTransform(1, Tone.NEUTRAL), toneOnly.apply(config).view());
        assertEquals(ViewTransform.DEFAULT, Config.defaults().view());
    }

    @Test
    void badValuesAreRefusedInWordsWithStatusTwo() throws IOException {
        Result r = run("--exposure", "17", "--output", dir.resolve("x.png").toString());
        assertEquals(2, r.status());
        assertEquals("glint: --exposure: expected a number of stops from -16 to 16, got +17", r.err().lines().findFirst().orElse(""));
        r = run("--exposure", "bright", "--output", dir.resolve("x.png").toString());
        assertEquals(2, r.status());
        assertEquals("glint: Invalid value for option '--exposure': 'bright' is not a number written with the digits "
                + "0-9 (as 1.5 or -2)", r.err().lines().findFirst().orElse(""));
        r = run("--tone", "filmic", "--output", dir.resolve("x.png").toString());
        assertEquals(2, r.status());
        assertEquals("glint: --tone: unknown tone curve 'filmic' (expected one of: standard, neutral)",
                r.err().lines().findFirst().orElse(""));

        Path scene = Files.writeString(dir.resolve("bad.yaml"), SCENE + "render:\n  exposure: 20\n");
        r = run("--scene", scene.toString(), "--output", dir.resolve("x.png").toString());
        assertEquals(2, r.status());
        assertEquals(scene + ":8:13: exposure must be a number of stops from -16 to 16, got 20", r.err().strip());
        scene = Files.writeString(dir.resolve("bad.yaml"), SCENE + "render: {tone: standrd}\n");
        r = run("--scene", scene.toString(), "--output", dir.resolve("x.png").toString());
        assertEquals(2, r.status());
        assertEquals(scene + ":7:16: unknown tone curve 'standrd' (did you mean 'standard'?)", r.err().strip());
        assertFalse(Files.exists(dir.resolve("x.png")));
    }

    @Test
    void aNegativeExposureIsAValueNotAnOption() throws IOException {
        Path png = still("dark.png", "--exposure", "-1");
        assertTrue(Files.size(png) > 0);
    }
}
