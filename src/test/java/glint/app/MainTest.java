package glint.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The command line of README.md ("Using it"): exit statuses, the messages on err, headless output. */
class MainTest {

    /** What one run of the program did. */
    private record Result(int status, String out, String err) {

        String firstErrLine() {
            return err.lines().findFirst().orElse("");
        }

        void assertNoStackTrace() {
            assertFalse(err.contains("Exception"), () -> "stack trace on err:\n" + err);
            assertFalse(err.contains("\tat "), () -> "stack trace on err:\n" + err);
            assertFalse(out.contains("Exception"), () -> "stack trace on out:\n" + out);
        }
    }

    private static final String TINY_SCENE = """
            camera: {position: [0, 1, -4], look_at: [0, 1, 0]}
            background: [0.1, 0.2, 0.3]
            lights:
              - {type: point, position: [-3, 5, -4], intensity: 50}
            objects:
              - {type: sphere, center: [0, 1, 0], radius: 1, material: {type: matte, color: [0.8, 0.2, 0.2]}}
              - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
            """;

    @TempDir
    Path dir;

    /** An empty config file, so that runs do not depend on ./config.properties. */
    private Path config;

    @BeforeEach
    void emptyConfig() throws IOException {
        config = Files.writeString(dir.resolve("empty.properties"), "");
    }

    private static Result run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = Main.run(args, new PrintWriter(out, true), new PrintWriter(err, true));
        return new Result(status, out.toString(), err.toString());
    }

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text);
    }

    // ---------------------------------------------------------------- bad arguments: status 2

    @Test
    void unknownOption() {
        Result r = run("--bogus");
        assertEquals(Main.BAD_INPUT, r.status());
        assertEquals("glint: unknown option '--bogus'", r.firstErrLine());
        assertTrue(r.err().contains("--help"));
        r.assertNoStackTrace();
    }

    @Test
    void optionWithoutItsValue() {
        Result r = run("--spp");
        assertEquals(2, r.status());
        assertEquals("glint: Missing required parameter for option '--spp' (N)", r.firstErrLine());
    }

    @Test
    void optionWithAValueOfTheWrongKind() {
        Result r = run("--width", "wide");
        assertEquals(2, r.status());
        assertEquals("glint: Invalid value for option '--width': 'wide' is not a whole number written with the digits 0-9", r.firstErrLine());
        r.assertNoStackTrace();
    }

    @Test
    void sppNotAPerfectSquare() {
        Result r = run("--config", config.toString(), "--spp", "3");
        assertEquals(2, r.status());
        assertEquals("glint: --spp: expected a perfect square from 1 to 4096 (1, 4, 9, 16, ...), got 3",
                r.firstErrLine());
        r.assertNoStackTrace();
    }

    @Test
    void unknownShadingModel() {
        Result r = run("--config", config.toString(), "--shading", "bogus");
        assertEquals(2, r.status());
        assertEquals("glint: --shading: unknown model 'bogus' (expected one of: cook-torrance, phong)",
                r.firstErrLine());
    }

    @Test
    void shadingTypoIsSuggested() {
        Result r = run("--config", config.toString(), "--shading", "phon");
        assertEquals(2, r.status());
        assertEquals("glint: --shading: unknown model 'phon' (did you mean 'phong'?)", r.firstErrLine());
    }

    @Test
    void widthOutOfRange() {
        Result r = run("--config", config.toString(), "--width", "0");
        assertEquals(2, r.status());
        assertEquals("glint: --width: expected a whole number from 1 to 65536, got 0", r.firstErrLine());
    }

    @Test
    void aHugeImageIsRefusedBeforeAnyMemoryIsTaken() {
        Result r = run("--config", config.toString(), "--width", "60000", "--height", "60000", "--output", "x.png");
        assertEquals(2, r.status());
        assertEquals("glint: --width x --height: 60000x60000 is 3600.0 megapixels; the largest image allowed is "
                + "33.2 megapixels (config key max_image_pixels)", r.firstErrLine());
    }

    @Test
    void depthOutOfRange() {
        Result r = run("--config", config.toString(), "--depth", "0");
        assertEquals(2, r.status());
        assertEquals("glint: --depth: expected a whole number from 1 to 64, got 0", r.firstErrLine());
    }

    @Test
    void outputOfAnUnsupportedKind() throws IOException {
        Path scene = write("tiny.yaml", TINY_SCENE);
        Result r = run("--config", config.toString(), "--scene", scene.toString(), "--output", "x.jpg");
        assertEquals(2, r.status());
        assertEquals("glint: --output: expected a file ending in .png or .pfm, got 'x.jpg'", r.firstErrLine());
        assertFalse(Files.exists(Path.of("x.jpg")));
    }

    @Test
    void outputInAMissingFolder() throws IOException {
        Path scene = write("tiny.yaml", TINY_SCENE);
        Path output = dir.resolve("no/such/folder/out.png");
        Result r = run("--config", config.toString(), "--scene", scene.toString(), "--output", output.toString());
        assertEquals(2, r.status());
        assertEquals("glint: --output: no such folder '" + output.getParent() + "'", r.firstErrLine());
    }

    @Test
    void outputAndBenchTogether() throws IOException {
        Path scene = write("tiny.yaml", TINY_SCENE);
        Result r = run("--config", config.toString(), "--scene", scene.toString(),
                "--output", dir.resolve("out.png").toString(), "--bench", "2");
        assertEquals(2, r.status());
        assertEquals("glint: --output and --bench cannot be used together", r.firstErrLine());
    }

    @Test
    void benchOfZeroFrames() throws IOException {
        Path scene = write("tiny.yaml", TINY_SCENE);
        Result r = run("--config", config.toString(), "--scene", scene.toString(), "--bench", "0");
        assertEquals(2, r.status());
        assertEquals("glint: --bench: expected a number of frames from 1 to 100000, got 0", r.firstErrLine());
    }

    // ---------------------------------------------------------------- bad files: status 2

    @Test
    void sceneWithATypo() throws IOException {
        Path scene = write("typo.yaml", """
                objects:
                  - type: sphere
                    radus: 1
                    center: [0, 1, 0]
                """);
        Result r = run("--config", config.toString(), "--scene", scene.toString(),
                "--output", dir.resolve("out.png").toString());
        assertEquals(Main.BAD_INPUT, r.status());
        assertEquals(scene + ":3:5: unknown key 'radus' in sphere (did you mean 'radius'?)", r.firstErrLine());
        assertTrue(r.firstErrLine().startsWith(scene.toString()));
        assertEquals(1, r.err().lines().count());
        r.assertNoStackTrace();
        assertFalse(Files.exists(dir.resolve("out.png")));
    }

    @Test
    void sceneWithATypoInBenchMode() throws IOException {
        Path scene = write("typo.yaml", "camera: {fvo: 60}\n");
        Result r = run("--config", config.toString(), "--scene", scene.toString(), "--bench", "1");
        assertEquals(2, r.status());
        assertEquals(scene + ":1:10: unknown key 'fvo' in camera (did you mean 'fov'?)", r.firstErrLine());
        r.assertNoStackTrace();
    }

    @Test
    void missingSceneFile() {
        Path scene = dir.resolve("missing.yaml");
        Result r = run("--config", config.toString(), "--scene", scene.toString(),
                "--output", dir.resolve("out.png").toString());
        assertEquals(2, r.status());
        assertEquals(scene + ": no such file", r.firstErrLine());
        r.assertNoStackTrace();
    }

    @Test
    void missingConfigFile() {
        Path missing = dir.resolve("nope.properties");
        Result r = run("--config", missing.toString(), "--output", dir.resolve("out.png").toString());
        assertEquals(2, r.status());
        assertEquals(missing + ": no such file", r.firstErrLine());
        r.assertNoStackTrace();
    }

    @Test
    void configWithABadKey() throws IOException {
        Path bad = write("bad.properties", "debug=false\nthreds=2\n");
        Result r = run("--config", bad.toString(), "--output", dir.resolve("out.png").toString());
        assertEquals(2, r.status());
        assertEquals(bad + ":2:1: unknown key 'threds' (did you mean 'threads'?)", r.firstErrLine());
        r.assertNoStackTrace();
    }

    @Test
    void configNamingAMissingScene() throws IOException {
        Path cfg = write("glint.properties", "scene=scenes/none.yaml\n");
        Result r = run("--config", cfg.toString(), "--output", dir.resolve("out.png").toString());
        assertEquals(2, r.status());
        // the error is at the config's scene line and says which folder the path was resolved against
        assertEquals(cfg + ":1:1: scene: no such file '" + dir.resolve("scenes/none.yaml") + "' (scene is resolved "
                + "against the config file's folder, " + dir.toAbsolutePath() + "); set scene in the config or use "
                + "--scene FILE", r.firstErrLine());
    }

    // ---------------------------------------------------------------- success: status 0

    @Test
    void helpExitsZero() {
        Result r = run("--help");
        assertEquals(0, r.status());
        assertTrue(r.out().contains("--scene"), r.out());
        assertTrue(r.out().contains("--output"), r.out());
    }

    @Test
    void headlessPngAndPfm() throws IOException {
        Path scene = write("tiny.yaml", TINY_SCENE);
        Path png = dir.resolve("out.png");
        Path pfm = dir.resolve("out.pfm");
        String[] common = {"--config", config.toString(), "--scene", scene.toString(),
            "--width", "8", "--height", "6", "--spp", "1", "--threads", "2"};

        Result r = run(concat(common, "--output", png.toString()));
        assertEquals(0, r.status(), r.err());
        assertEquals("", r.err());
        assertTrue(r.out().startsWith("wrote " + png + " (8x6, 1 spp, 2 threads, cook-torrance, depth 16) in "),
                r.out());
        BufferedImage image = ImageIO.read(png.toFile());
        assertNotNull(image, "not a readable PNG");
        assertEquals(8, image.getWidth());
        assertEquals(6, image.getHeight());

        Result r2 = run(concat(common, "--output", pfm.toString()));
        assertEquals(0, r2.status(), r2.err());
        byte[] bytes = Files.readAllBytes(pfm);
        byte[] header = "PF\n8 6\n-1.0\n".getBytes(StandardCharsets.US_ASCII);
        assertEquals(12, header.length);
        assertArrayEquals(header, Arrays.copyOf(bytes, header.length));
        assertEquals(header.length + 8 * 6 * 3 * Float.BYTES, bytes.length); // 12 + 576 = 588
        ByteBuffer body = ByteBuffer.wrap(bytes, header.length, bytes.length - header.length)
                .order(ByteOrder.LITTLE_ENDIAN);
        while (body.hasRemaining()) {
            float value = body.getFloat();
            assertTrue(Float.isFinite(value) && value >= 0, "pixel value " + value);
        }
    }

    @Test
    void aRayThatHitsNothingHasTheBackgroundRadiance() throws IOException {
        Path scene = write("empty.yaml", "background: [0.25, 0.5, 1]\n");
        Path pfm = dir.resolve("sky.pfm");
        Result r = run("--config", config.toString(), "--scene", scene.toString(), "--width", "4", "--height", "3",
                "--spp", "4", "--output", pfm.toString());
        assertEquals(0, r.status(), r.err());
        byte[] bytes = Files.readAllBytes(pfm);
        assertEquals("PF\n4 3\n-1.0\n".length() + 4 * 3 * 12, bytes.length);
        ByteBuffer body = ByteBuffer.wrap(bytes, 12, bytes.length - 12).order(ByteOrder.LITTLE_ENDIAN);
        for (int i = 0; i < 4 * 3; i++) {
            assertEquals(0.25f, body.getFloat());
            assertEquals(0.5f, body.getFloat());
            assertEquals(1f, body.getFloat());
        }
    }

    @Test
    void theConfigSceneIsResolvedAgainstTheConfigFolder() throws IOException {
        Path sub = Files.createDirectories(dir.resolve("project/scenes"));
        Files.writeString(sub.resolve("tiny.yaml"), TINY_SCENE);
        Path cfg = Files.writeString(dir.resolve("project/glint.properties"),
                "scene=scenes/tiny.yaml\ndisplay_width=5\ndisplay_height=4\nsamples=1\nshading=phong\n");
        Path png = dir.resolve("from-config.png");
        Result r = run("--config", cfg.toString(), "--output", png.toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().startsWith("wrote " + png + " (5x4, 1 spp, "), r.out());
        assertTrue(r.out().contains(", phong, depth 16)"), r.out());
        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(5, image.getWidth());
        assertEquals(4, image.getHeight());
    }

    @Test
    void benchPrintsWhatItRendersThenOneLinePerFrameThenTheSummary() throws IOException {
        Path scene = write("tiny.yaml", TINY_SCENE);
        Result r = run("--config", config.toString(), "--scene", scene.toString(), "--width", "8", "--height", "6",
                "--spp", "1", "--threads", "1", "--bench", "3");
        assertEquals(0, r.status(), r.err());
        String[] lines = r.out().split("\n");
        assertEquals(5, lines.length, r.out());
        assertEquals("timing 3 frames of " + scene + " (8x6, 1 spp, 1 threads, cook-torrance, depth 16)", lines[0]);
        for (int i = 1; i <= 3; i++) {
            assertTrue(lines[i].matches("frame " + i + ": \\d+\\.\\d\\d ms, render cpu \\d+\\.\\d\\d ms"), lines[i]);
        }
        assertTrue(lines[4].matches("bench: frames=3 median_ms=\\d+\\.\\d\\d p95_ms=\\d+\\.\\d\\d rays_per_s=\\d+"),
                lines[4]);
    }

    private static String[] concat(String[] first, String... more) {
        String[] all = Arrays.copyOf(first, first.length + more.length);
        System.arraycopy(more, 0, all, first.length, more.length);
        return all;
    }

    // ---------------------------------------------------------------- hostile arguments and output

    @Test
    void digitsOfOtherScriptsAreNotANumber() {
        // Arabic-Indic 64: Java's own parser would take it as 64
        Result r = run("--config", config.toString(), "--width", "\u0666\u0664");
        assertEquals(2, r.status());
        assertEquals("glint: Invalid value for option '--width': '\u0666\u0664' is not a whole number written with the "
                + "digits 0-9", r.firstErrLine());
    }

    @Test
    void anEmptySceneNameIsNotTheCurrentFolder() {
        Result r = run("--config", config.toString(), "--scene", "", "--output", dir.resolve("o.png").toString());
        assertEquals(2, r.status());
        assertEquals("glint: --scene: expected a file name, got nothing", r.firstErrLine());
    }

    @Test
    void anOutputThatIsAFolderIsRefusedBeforeTheSceneIsRead() throws IOException {
        Path folder = Files.createDirectory(dir.resolve("renders.png"));
        // the scene does not exist: the output is checked first, so no render is ever started
        Result r = run("--config", config.toString(), "--scene", dir.resolve("none.yaml").toString(),
                "--output", folder.toString());
        assertEquals(2, r.status());
        assertEquals("glint: --output: '" + folder + "' is a folder; expected an image file name such as out.png",
                r.firstErrLine());
    }

    @Test
    void anOutputNameEndingInASlashIsRefusedAsCpRefusesIt() throws IOException {
        Path scene = write("tiny.yaml", TINY_SCENE);
        Path old = Files.writeString(dir.resolve("old.png"), "old");
        // "new.png/" would become the path new.png, and "old.png/" replace old.png: cp and > refuse both
        Result r = run("--config", config.toString(), "--scene", scene.toString(), "--output", dir + "/new.png/");
        assertEquals(2, r.status());
        assertEquals("glint: --output: '" + dir + "/new.png/' ends in '/', so it names a folder, and there is no folder '"
                + dir + "/new.png'; write the file name without the '/'", r.firstErrLine());
        r = run("--config", config.toString(), "--scene", scene.toString(), "--output=" + dir + "/old.png/");
        assertEquals(2, r.status());
        assertEquals("glint: --output: '" + dir + "/old.png/' ends in '/', so it names a folder, and '" + dir
                + "/old.png' is a file; write the file name without the '/'", r.firstErrLine());
        assertEquals("old", Files.readString(old));
        try (var files = Files.list(dir)) {
            assertEquals(List.of("empty.properties", "old.png", "tiny.yaml"),
                    files.map(f -> f.getFileName().toString()).sorted().toList(), "nothing written");
        }
        r.assertNoStackTrace();
    }

    @Test
    void aSceneOrConfigNameEndingInASlashIsRefused() throws IOException {
        Path scene = write("tiny.yaml", TINY_SCENE);
        Result r = run("--config", config.toString(), "--scene", scene + "/", "--output", dir.resolve("x.png").toString());
        assertEquals(2, r.status());
        assertEquals("glint: --scene: '" + scene + "/' ends in '/', so it names a folder, and '" + scene
                + "' is a file; write the file name without the '/'", r.firstErrLine());
        r = run("--config", config + "/", "--scene", scene.toString(), "--output", dir.resolve("x.png").toString());
        assertEquals(2, r.status());
        assertEquals("glint: --config: '" + config + "/' ends in '/', so it names a folder, and '" + config
                + "' is a file; write the file name without the '/'", r.firstErrLine());
        Path cfg = write("slash.properties", "threads=1\nscene=tiny.yaml/\n");
        r = run("--config", cfg.toString(), "--output", dir.resolve("x.png").toString());
        assertEquals(2, r.status());
        assertEquals(cfg + ":2:1: scene: '" + scene + "/' ends in '/', so it names a folder, and '" + scene
                + "' is a file; write the file name without the '/'", r.firstErrLine());
        // a folder named with its slash is a folder, as before
        Path folder = Files.createDirectory(dir.resolve("renders.png"));
        r = run("--config", config.toString(), "--scene", scene.toString(), "--output", folder + "/");
        assertEquals("glint: --output: '" + folder + "' is a folder; expected an image file name such as out.png",
                r.firstErrLine());
    }

    @Test
    void anOutputThatIsAPipeIsRefused() throws Exception {
        Path scene = write("tiny.yaml", TINY_SCENE);
        Path pipe = dir.resolve("pipe.png");
        assertEquals(0, new ProcessBuilder("mkfifo", pipe.toString()).start().waitFor(), "mkfifo");
        Result r = run("--config", config.toString(), "--scene", scene.toString(), "--output", pipe.toString());
        assertEquals(2, r.status());
        assertEquals("glint: --output: '" + pipe + "' is not a regular file (a pipe or device); expected an image "
                + "file name such as out.png", r.firstErrLine());
    }

    @Test
    void aBillionBenchFramesAreRefusedUpFront() throws IOException {
        Path scene = write("tiny.yaml", TINY_SCENE);
        Result r = run("--config", config.toString(), "--scene", scene.toString(), "--bench", "1000000000");
        assertEquals(2, r.status());
        assertEquals("glint: --bench: expected a number of frames from 1 to 100000, got 1000000000", r.firstErrLine());
        r.assertNoStackTrace();
    }

    @Test
    void aSceneRendersAtDepth64() throws IOException {
        Path scene = write("tiny.yaml", TINY_SCENE);
        Path out = dir.resolve("deep.png");
        Result r = run("--config", config.toString(), "--scene", scene.toString(), "--output", out.toString(),
                "--width", "16", "--height", "12", "--depth", "64");
        assertEquals(0, r.status(), r.err());
        assertTrue(Files.size(out) > 0);
    }

    @Test
    void aSceneLimitOfOneByteSaysBytesNotZeroMegabytes() throws IOException {
        Path scene = write("tiny.yaml", TINY_SCENE);
        Path cfg = write("one.properties", "max_scene_bytes=1\n");
        Result r = run("--config", cfg.toString(), "--scene", scene.toString(), "--output", dir.resolve("o.png").toString());
        assertEquals(2, r.status());
        assertEquals(scene + ": the file is " + Files.size(scene) + " bytes; the largest scene accepted is 1 byte "
                + "(config key max_scene_bytes)", r.firstErrLine());
    }

    @Test
    void aConfigCopiedElsewhereSaysTheDefaultSceneIsResolvedAgainstItsFolder() throws IOException {
        Path copied = Files.createDirectory(dir.resolve("copied"));
        Path cfg = Files.writeString(copied.resolve("config.properties"), "threads=1\n");
        Result r = run("--config", cfg.toString(), "--output", dir.resolve("o.png").toString());
        assertEquals(2, r.status());
        assertEquals(cfg + ": no such scene file '" + copied.resolve("scenes/default.yaml") + "' (scene is resolved "
                + "against the config file's folder, " + copied.toAbsolutePath() + "; the default is "
                + "scenes/default.yaml); set scene in the config or use --scene FILE", r.firstErrLine());
    }

    @Test
    void aWindowSizeOfADoubleMaxImageIsRefusedNotOverflowed() throws IOException {
        Path cfg = write("huge.properties", "max_image_pixels=700000000\ndisplay_width=65536\ndisplay_height=65536\n");
        Result r = run("--config", cfg.toString(), "--scene", Path.of("scenes/default.yaml").toAbsolutePath().toString(),
                "--output", dir.resolve("o.png").toString());
        assertEquals(2, r.status());
        // 65536 x 65536 = 4,294,967,296 pixels: computed in long, not wrapped to 0 in int
        assertEquals(cfg + ":2:1: display_width x display_height: 65536x65536 is 4295.0 megapixels; the largest "
                + "image allowed is 700.0 megapixels (config key max_image_pixels)", r.firstErrLine());
    }
}
