package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A scene's render: block ranks above config.properties and below the command line's flags. */
class RenderBlockRankingTest {

    private static final String SCENE = """
            camera: {position: [0, 1, -4], look_at: [0, 1, 0]}
            lights:
              - {type: point, position: [-3, 5, -4], intensity: 50}
            objects:
              - {type: sphere, center: [0, 1, 0], radius: 1}
            """;

    @TempDir
    Path dir;

    private String run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = Main.run(args, new PrintWriter(out, true), new PrintWriter(err, true));
        assertEquals(0, status, () -> "status " + status + ": " + err);
        return out.toString();
    }

    private String still(Path scene, Path config, String... flags) {
        String[] args = new String[flags.length + 6];
        args[0] = "--scene";
        args[1] = scene.toString();
        args[2] = "--config";
        args[3] = config.toString();
        args[4] = "--output";
        args[5] = dir.resolve("out.png").toString();
        System.arraycopy(flags, 0, args, 6, flags.length);
        return run(args);
    }

    @Test
    void theBlockBeatsTheConfigAndAFlagBeatsTheBlock() throws IOException {
        Path config = Files.writeString(dir.resolve("c.properties"),
                "shading=cook-torrance\nsamples=4\nrecursion_max=16\ndisplay_width=40\ndisplay_height=30\n");
        Path plain = Files.writeString(dir.resolve("plain.yaml"), SCENE);
        Path styled = Files.writeString(dir.resolve("styled.yaml"), SCENE
                + "render: {shading: phong, samples: 9, recursion_max: 3, width: 32, height: 24}\n");
        assertTrue(still(plain, config).contains("(40x30, 4 spp, "), "the config alone");
        assertTrue(still(plain, config).contains("cook-torrance, depth 16)"), "the config alone");
        String block = still(styled, config);
        assertTrue(block.contains("(32x24, 9 spp, ") && block.contains("phong, depth 3)"), block);
        String flags = still(styled, config, "--shading", "cook-torrance", "--spp", "1", "--depth", "5",
                "--width", "20", "--height", "10");
        assertTrue(flags.contains("(20x10, 1 spp, ") && flags.contains("cook-torrance, depth 5)"), flags);
        String width = still(styled, config, "--width", "16");
        assertTrue(width.contains("(16x24, 9 spp, "), "a flag replaces only what it names: " + width);
    }

    /** The limits hold for the result: a config's own size beyond them yields to the flags or a block that set another. */
    @Test
    void aConfigWhoseOwnSizeBreaksItsLimitRendersAtTheSizeOfTheFlagsOrTheBlock() throws IOException {
        Path config = Files.writeString(dir.resolve("big.properties"), "display_width=20000\ndisplay_height=20000\n");
        Path plain = Files.writeString(dir.resolve("plain.yaml"), SCENE);
        assertTrue(still(plain, config, "--width", "40", "--height", "30").contains("(40x30, 4 spp, "), "the flags' size");
        Path sized = Files.writeString(dir.resolve("sized.yaml"), SCENE + "render: {width: 32, height: 24}\n");
        assertTrue(still(sized, config).contains("(32x24, 4 spp, "), "the block's size");
        StringWriter err = new StringWriter();
        int status = Main.run(new String[] {"--scene", plain.toString(), "--config", config.toString(), "--output",
            dir.resolve("big.png").toString()}, new PrintWriter(new StringWriter(), true), new PrintWriter(err, true));
        assertEquals(2, status);
        assertEquals(config + ":1:1: display_width x display_height: 20000x20000 is 400.0 megapixels; the largest image "
                + "allowed is 33.2 megapixels (config key max_image_pixels)" + System.lineSeparator(), err.toString());
        assertTrue(!Files.exists(dir.resolve("big.png")));
    }

    @Test
    void phongClassicIsSeenInPhongWithTheShippedConfig() {
        Path root = Path.of("").toAbsolutePath();
        String out = run("--config", root.resolve("config.properties").toString(), "--scene",
                root.resolve("scenes/phong-classic.yaml").toString(), "--width", "16", "--height", "9",
                "--output", dir.resolve("p.png").toString());
        assertTrue(out.contains("phong, depth"), out);
    }

    @Test
    void aBlockBeyondTheConfigsLimitsIsAPositionedError() throws IOException {
        Path config = Files.writeString(dir.resolve("small.properties"), "max_recursion=8\nmax_image_pixels=100\ndisplay_width=5\ndisplay_height=5\n");
        Path deep = Files.writeString(dir.resolve("deep.yaml"), SCENE + "render: {recursion_max: 9}\n");
        StringWriter err = new StringWriter();
        int status = Main.run(new String[] {"--scene", deep.toString(), "--config", config.toString(),
            "--output", dir.resolve("d.png").toString(), "--width", "5", "--height", "5"},
                new PrintWriter(new StringWriter(), true), new PrintWriter(err, true));
        assertEquals(Main.BAD_INPUT, status);
        assertEquals(deep + ":6:25: recursion_max in render must be at most 8 (config key max_recursion), got 9",
                err.toString().strip());
        Path big = Files.writeString(dir.resolve("big.yaml"), SCENE + "render: {width: 20, height: 20}\n");
        err.getBuffer().setLength(0);
        status = Main.run(new String[] {"--scene", big.toString(), "--config", config.toString(),
            "--output", dir.resolve("b.png").toString()},
                new PrintWriter(new StringWriter(), true), new PrintWriter(err, true));
        assertEquals(Main.BAD_INPUT, status);
        assertTrue(err.toString().startsWith(big + ":6:17: width x height in render: 20x20 is"), err.toString());
    }
}
