package glint.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.config.ConfigLoader;
import glint.config.Flags;
import glint.scene.RenderBlock;
import glint.scenefile.SceneLoader;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code --noise T}: a path or bdpt still sampled pixel by pixel until each one's noise is below T, at most
 * {@code max_samples}; its report states the samples spent; the same bytes at any thread count and tile size; the
 * settings ranked as every other; bad values refused in words.
 */
class AdaptiveStillTest {

    private static final String SCENE = """
            camera: {position: [0, 1, -4], look_at: [0, 1, 0]}
            background: [0.4, 0.5, 0.8]
            lights:
              - {type: point, position: [-3, 5, -4], radius: 0.5, intensity: 80}
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

    private Result still(String name, String config, String... flags) throws IOException {
        Path scene = Files.writeString(dir.resolve("scene.yaml"), SCENE);
        Path c = Files.writeString(dir.resolve(name + ".properties"), "display_width=24\ndisplay_height=18\n" + config);
        String[] args = new String[flags.length + 6];
        System.arraycopy(new String[] {"--scene", scene.toString(), "--config", c.toString(), "--output",
                dir.resolve(name).toString()}, 0, args, 0, 6);
        System.arraycopy(flags, 0, args, 6, flags.length);
        return run(args);
    }

    @Test
    void theReportStatesTheSamplesSpentAndTheBytesDoNotDependOnThreadsOrTiles() throws IOException {
        Result r = still("a.png", "threads=1\nscreen_divider=1\n", "--integrator", "path", "--noise", "0.05",
                "--max-samples", "200");
        assertEquals(0, r.status(), r::err);
        assertTrue(r.out().startsWith("wrote " + dir.resolve("a.png") + " (24x18, noise 5 %, at most 200 spp, 1 threads, "
                + "cook-torrance, path, depth 16) in "), r.out());
        Matcher m = Pattern.compile("\nsamples spent: ([0-9.]+) spp on average, ([0-9]+) to ([0-9]+)\n$").matcher(r.out());
        assertTrue(m.find(), r.out());
        double mean = Double.parseDouble(m.group(1));
        assertEquals(64, Integer.parseInt(m.group(2)), "the sky stops at the minimum");
        int most = Integer.parseInt(m.group(3));
        assertTrue(most > 64 && most <= 200 && mean > 64 && mean < most, r.out());
        byte[] bytes = Files.readAllBytes(dir.resolve("a.png"));
        for (String config : new String[] {"threads=2\nscreen_divider=8\n", "threads=7\nscreen_divider=13\n"}) {
            Result again = still("b.png", config, "--integrator", "path", "--noise", "0.05", "--max-samples", "200");
            assertEquals(0, again.status(), again::err);
            assertTrue(again.out().endsWith(m.group()), again.out());
            assertArrayEquals(bytes, Files.readAllBytes(dir.resolve("b.png")), config);
        }
    }

    @Test
    void withoutANoiseOrWithWhittedAStillTakesItsSamples() throws IOException {
        Result r = still("w.png", "noise=0.05\nsamples=4\n");
        assertEquals(0, r.status(), r::err);
        assertTrue(r.out().contains("(24x18, 4 spp, "), r.out());
        assertTrue(!r.out().contains("samples spent"), r.out());
        Result p = still("p.png", "samples=4\nintegrator=path\n");
        assertTrue(p.out().contains("(24x18, 4 spp, ") && !p.out().contains("samples spent"), p.out());
    }

    @Test
    void theFlagBeatsTheBlockWhichBeatsTheConfig() throws Exception {
        Config config = ConfigLoader.parse("c.properties", "noise=0.1\nmax_samples=300\n");
        RenderBlock block = SceneLoader.parse("s.yaml", SCENE + "render: {noise: 0.05, max_samples: 200}\n").render();
        Config fromBlock = Flags.NONE.effective(config, block);
        assertEquals(0.05, fromBlock.noise());
        assertEquals(200, fromBlock.maxSamples());
        Flags flags = new Flags(null, null, null, null, null, null, null, null, null, 0.02, 100);
        Config fromFlags = flags.effective(config, block);
        assertEquals(0.02, fromFlags.noise());
        assertEquals(100, fromFlags.maxSamples());
        assertEquals(0.1, Flags.NONE.effective(config, RenderBlock.NONE).noise());
    }

    @Test
    void badValuesAreRefusedInWords() throws IOException {
        Result noise = still("x.png", "", "--noise", "2");
        assertEquals(2, noise.status());
        assertEquals("glint: --noise: expected 0 (off) or a number from 0.0001 to 1, got 2\n", noise.err());
        Result tiny = still("x.png", "", "--noise", "0.00001");
        assertEquals("glint: --noise: expected 0 (off) or a number from 0.0001 to 1, got 0.00001\n", tiny.err());
        Result cap = still("x.png", "", "--max-samples", "0");
        assertEquals(2, cap.status());
        assertEquals("glint: --max-samples: expected a whole number from 1 to 65536, got 0\n", cap.err());
        Result block = run("--scene", Files.writeString(dir.resolve("b.yaml"), SCENE
                + "render: {noise: 0.5%}\n").toString(), "--output", dir.resolve("y.png").toString());
        assertEquals(2, block.status());
        assertTrue(block.err().startsWith(dir.resolve("b.yaml") + ":8:17: "), block.err());
    }
}
