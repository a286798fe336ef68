package glint.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.ViewTransform;
import glint.input.InputException;
import glint.render.Shading;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ConfigLoaderTest {

    private static final String FILE = "config.properties";

    private static Config parse(String text) throws InputException {
        return ConfigLoader.parse(FILE, text);
    }

    private static void assertError(String expected, String text) {
        InputException e = assertThrows(InputException.class, () -> parse(text));
        assertEquals(expected, e.getMessage());
    }

    /** A size beyond the limit, refused on the settings a scene is rendered with (no block, no flag), at its line. */
    private static void assertSizeError(String expected, String text) {
        InputException e = assertThrows(InputException.class,
                () -> Flags.NONE.effective(parse(text), glint.scene.RenderBlock.NONE));
        assertEquals(expected, e.getMessage());
    }

    // ---------------------------------------------------------------- defaults

    @Test
    void emptyFileGivesTheDefaults() throws InputException {
        assertEquals(Config.defaults(), parse(""));
        assertEquals(Config.defaults(), parse("# only comments\n! and these\n\n"));
    }

    @Test
    void defaultValues() {
        Config d = Config.defaults();
        assertFalse(d.debug());
        assertEquals(1e-9, d.epsilon());
        assertEquals(2, d.displayScale());
        assertEquals(8, d.screenDivider());
        assertEquals(600, d.displayHeight());
        assertEquals(16, d.recursionMax());
        assertEquals(800, d.displayWidth());
        assertEquals("Glint", d.name());
        assertEquals("scenes/default.yaml", d.scene());
        assertEquals(0, d.threads());
        assertEquals(Shading.COOK_TORRANCE, d.shading());
        assertEquals(4, d.samples());
        assertEquals(1e-2, d.minWeight());
        assertEquals(2.0, d.moveSpeed());
        assertEquals(60, d.turnSpeed());
        assertEquals(30, d.targetFps());
    }

    @Test
    void missingKeysKeepTheirDefaults() throws InputException {
        Config c = parse("threads=3\n");
        assertEquals(Config.defaults().withThreads(3), c);
    }

    // ---------------------------------------------------------------- every key

    @Test
    void everyKeyIsParsed() throws InputException {
        Config c = parse("""
                debug=true
                epsilon=1e-6
                display_scale=1.5
                screen_divider=4
                display_height=480
                recursion_max=7
                display_width=640
                name=My Glint
                scene=scenes/other.yaml
                threads=3
                shading=phong
                samples=16
                min_weight=0.01
                move_speed=3.5
                turn_speed=90
                target_fps=24
                free_flight=true
                exposure=-1.5
                tone=standard
                max_image_pixels=1000000
                max_scene_bytes=4096
                max_objects=10
                max_lights=2
                max_recursion=8
                """);
        assertEquals(new Config(true, 1e-6, 1.5, 4, 640, 480, 7, "My Glint", "scenes/other.yaml", 3,
                Shading.PHONG, 16, 0.01, 3.5, 90, 24, new Limits(1_000_000, 4096, 10, 2, 8), true)
                .withView(new ViewTransform(-1.5, ViewTransform.Tone.STANDARD))
                .withSizeSetAt(new Config.Place("config.properties", 7, 1)), c); // display_width's line
    }

    @Test
    void theViewTransformIsNeutralAtNoExposureUnlessTheConfigSaysOtherwise() throws InputException {
        assertEquals(new ViewTransform(0, ViewTransform.Tone.NEUTRAL), parse("").view());
        assertEquals(new ViewTransform(16, ViewTransform.Tone.NEUTRAL), parse("exposure=16\n").view());
        assertEquals(new ViewTransform(-16, ViewTransform.Tone.STANDARD), parse("exposure=-16\ntone=standard\n").view());
        assertEquals(new ViewTransform(0.25, ViewTransform.Tone.NEUTRAL), parse("exposure=+.25\ntone=neutral\n").view());
    }

    @Test
    void aBadExposureOrToneIsReportedAtItsLine() {
        assertError("config.properties:2:1: exposure: expected a number of stops from -16 to 16, got '17'",
                "debug=false\nexposure=17\n");
        assertError("config.properties:1:1: exposure: expected a number of stops from -16 to 16, got 'bright'",
                "exposure=bright\n");
        assertError("config.properties:1:1: tone: unknown tone curve 'filmic' (expected one of: standard, neutral)",
                "tone=filmic\n");
        assertError("config.properties:1:1: tone: unknown tone curve 'nuetral' (did you mean 'neutral'?)", "tone=nuetral\n");
    }

    @Test
    void noiseAndMaxSamplesSetAdaptiveSampling() throws InputException {
        Config d = parse("");
        assertEquals(0, d.noise());
        assertEquals(1024, d.maxSamples());
        assertEquals(glint.render.Convergence.WINDOW_NOISE, d.windowNoise());
        Config c = parse("noise=0.02\nmax_samples=256\nintegrator=path\n");
        assertEquals(0.02, c.noise());
        assertEquals(0.02, c.windowNoise());
        assertEquals(256, c.maxSamples());
        assertTrue(c.adaptiveStill());
        assertFalse(parse("noise=0.02\n").adaptiveStill(), "whitted's stills keep their samples");
        assertEquals(1e-4, parse("noise=0.0001\n").noise());
        assertEquals(65536, parse("max_samples=65536\n").maxSamples());
    }

    @Test
    void aBadNoiseOrMaxSamplesIsReportedAtItsLine() {
        assertError("config.properties:2:1: noise: expected 0 (off) or a number from 0.0001 to 1, got '0.00001'",
                "debug=false\nnoise=0.00001\n");
        assertError("config.properties:1:1: noise: expected 0 (off) or a number from 0.0001 to 1, got '2'", "noise=2\n");
        assertError("config.properties:1:1: noise: expected 0 (off) or a number from 0.0001 to 1, got '-0.01'",
                "noise=-0.01\n");
        assertError("config.properties:1:1: noise: expected 0 (off) or a number from 0.0001 to 1, got '1%'",
                "noise=1%\n");
        assertError("config.properties:1:1: max_samples: expected a whole number from 1 to 65536, got '0'",
                "max_samples=0\n");
        assertError("config.properties:1:1: max_samples: expected a whole number from 1 to 65536, got '65537'",
                "max_samples=65537\n");
    }

    @Test
    void everyKeyOfKeysIsTestedAbove() {
        assertEquals(List.of("debug", "epsilon", "display_scale", "screen_divider", "display_height",
                "recursion_max", "display_width", "name", "scene", "threads", "shading", "integrator", "samples",
                "noise", "max_samples", "min_weight", "move_speed", "turn_speed", "target_fps", "free_flight", "exposure", "tone", "max_image_pixels",
                "max_scene_bytes", "max_objects", "max_lights", "max_recursion"), List.copyOf(ConfigLoader.KEYS));
    }

    @Test
    void propertiesSyntaxVariants() throws InputException {
        Config c = parse("""
                  threads = 2
                samples: 9
                debug TRUE
                shading=cook-torrance   \s
                """);
        assertEquals(2, c.threads());
        assertEquals(9, c.samples());
        assertTrue(c.debug());
        assertEquals(Shading.COOK_TORRANCE, c.shading());
    }

    @Test
    void rangeLimitsAreAccepted() throws InputException {
        Config low = parse("display_scale=1\nscreen_divider=1\nrecursion_max=1\ndisplay_width=1\ndisplay_height=1\n"
                + "threads=0\nsamples=1\nmin_weight=0\ntarget_fps=1\n");
        assertEquals(1, low.displayScale());
        assertEquals(1, low.samples());
        assertEquals(0, low.minWeight());
        Config high = parse("display_scale=64\nscreen_divider=256\nrecursion_max=64\ndisplay_width=7680\n"
                + "display_height=4320\nthreads=1024\nsamples=4096\nmin_weight=1\ntarget_fps=1000\n");
        assertEquals(7680, high.displayWidth());
        assertEquals(4096, high.samples());
    }

    @Test
    void theRepositoryConfigLoadsAndNamesAnExistingScene() throws InputException {
        Path config = Path.of("config.properties");
        Config c = ConfigLoader.load(config);
        Path scene = config.toAbsolutePath().getParent().resolve(c.scene());
        assertTrue(Files.isRegularFile(scene), () -> "missing " + scene);
    }

    // ---------------------------------------------------------------- unknown keys

    @Test
    void unknownKeyWithSuggestionAndLine() {
        assertError("config.properties:3:1: unknown key 'threds' (did you mean 'threads'?)", """
                # Glint settings
                debug=false
                threds=2
                samples=4
                """);
    }

    @Test
    void unknownIndentedKeyHasItsColumn() {
        assertError("config.properties:2:4: unknown key 'recurson_max' (did you mean 'recursion_max'?)", """
                name=x
                   recurson_max = 3
                """);
    }

    @Test
    void unknownKeyFarFromAnyListsTheKeys() {
        assertError("config.properties:1:1: unknown key 'colour' (expected one of: debug, epsilon, display_scale, "
                + "screen_divider, display_height, recursion_max, display_width, name, scene, threads, shading, "
                + "integrator, samples, noise, max_samples, min_weight, move_speed, turn_speed, target_fps, free_flight, exposure, tone, "
                + "max_image_pixels, max_scene_bytes, max_objects, "
                + "max_lights, max_recursion)", "colour=red\n");
    }

    @Test
    void theFirstUnknownKeyInTheFileIsReported() {
        assertError("config.properties:2:1: unknown key 'sampels' (did you mean 'samples'?)", """
                debug=false
                sampels=4
                threds=2
                shadin=phong
                """);
    }

    // ---------------------------------------------------------------- malformed values

    @Test
    void epsilonNotANumber() {
        assertError("config.properties:2:1: epsilon: expected a positive number, got 'abc'", "debug=true\nepsilon=abc\n");
    }

    @Test
    void epsilonZero() {
        assertError("config.properties:1:1: epsilon: expected a positive number, got '0'", "epsilon=0\n");
    }

    @Test
    void javaFloatSuffixIsNotANumber() {
        assertError("config.properties:1:1: epsilon: expected a positive number, got '1e-9d'", "epsilon=1e-9d\n");
    }

    @Test
    void infinityIsNotANumberHere() {
        assertError("config.properties:1:1: move_speed: expected a positive number, got 'Infinity'",
                "move_speed=Infinity\n");
    }

    @Test
    void samplesNotAPerfectSquare() {
        assertError("config.properties:3:1: samples: expected a perfect square (1, 4, 9, 16, ...), got '3'", """
                threads=2

                samples=3
                """);
    }

    @Test
    void samplesZero() {
        assertError("config.properties:1:1: samples: expected a whole number from 1 to 4096, got '0'", "samples=0\n");
    }

    @Test
    void shadingTypoWithSuggestion() {
        assertError("config.properties:1:1: shading: unknown model 'phon' (did you mean 'phong'?)", "shading=phon\n");
    }

    @Test
    void shadingFarFromAnyListsTheModels() {
        assertError("config.properties:1:1: shading: unknown model 'pbr' (expected one of: cook-torrance, phong)",
                "shading=pbr\n");
    }

    @Test
    void screenDividerZero() {
        assertError("config.properties:2:1: screen_divider: expected a whole number from 1 to 256, got '0'",
                "# tiles\nscreen_divider=0\n");
    }

    @Test
    void debugMaybe() {
        assertError("config.properties:1:1: debug: expected true or false, got 'maybe'", "debug=maybe\n");
    }

    @Test
    void wholeNumberWithADecimalPoint() {
        assertError("config.properties:1:1: display_width: expected a whole number from 1 to 65536, got '800.5'",
                "display_width=800.5\n");
    }

    @Test
    void negativeThreads() {
        assertError("config.properties:1:3: threads: expected a whole number from 0 to 1024, got '-1'",
                "  threads = -1\n");
    }

    @Test
    void recursionMaxZero() {
        assertError("config.properties:1:1: recursion_max: expected a whole number from 1 to 64, got '0'",
                "recursion_max=0\n");
    }

    @Test
    void displayScaleBelowOne() {
        assertError("config.properties:1:1: display_scale: expected a number from 1 to 64, got '0.5'",
                "display_scale=0.5\n");
    }

    @Test
    void minWeightAboveOne() {
        assertError("config.properties:1:1: min_weight: expected a number from 0 to 1, got '2'", "min_weight=2\n");
    }

    @Test
    void targetFpsZero() {
        assertError("config.properties:1:1: target_fps: expected a number from 1 to 1000, got '0'", "target_fps=0\n");
    }

    @Test
    void emptyScene() {
        assertError("config.properties:1:1: scene: expected a scene file path, got nothing", "scene=\n");
    }

    @Test
    void emptyValueOfANumber() {
        assertError("config.properties:1:1: threads: expected a whole number from 0 to 1024, got ''", "threads=\n");
    }

    @Test
    void aKeySetTwiceIsReportedWhereTheValueThatCountsIs() {
        // java.util.Properties keeps the last value, so the message points at the last line
        assertError("config.properties:3:1: threads: expected a whole number from 0 to 1024, got 'many'", """
                threads=2
                samples=4
                threads=many
                """);
    }

    @Test
    void keyThatPrefixesAnotherIsFoundOnItsOwnLine() {
        // the line "scene=..." must not be mistaken for the line of "scen"
        assertError("config.properties:2:1: unknown key 'scen' (did you mean 'scene'?)", """
                name=x
                scen=a.yaml
                scene=b.yaml
                """);
    }

    @Test
    void malformedUnicodeEscape() {
        // the escape (a backslash, u and four letters that are not hex) starts in column 6
        assertError("config.properties:1:6: a \\u escape needs four hex digits, as in \\u00e9", "name=\\uZZZZ\n");
    }

    // ---------------------------------------------------------------- files

    @Test
    void missingFile(@TempDir Path dir) {
        Path path = dir.resolve("nope.properties");
        InputException e = assertThrows(InputException.class, () -> ConfigLoader.load(path));
        assertEquals(path + ": no such file", e.getMessage());
    }

    @Test
    void loadNamesTheFileByItsPath(@TempDir Path dir) throws IOException {
        Path path = dir.resolve("glint.properties");
        Files.writeString(path, "samples=2\n");
        InputException e = assertThrows(InputException.class, () -> ConfigLoader.load(path));
        assertEquals(path + ":1:1: samples: expected a perfect square (1, 4, 9, 16, ...), got '2'", e.getMessage());
    }

    @Test
    void perfectSquares() {
        assertTrue(Config.isPerfectSquare(1));
        assertTrue(Config.isPerfectSquare(4));
        assertTrue(Config.isPerfectSquare(9));
        assertTrue(Config.isPerfectSquare(4096));
        assertFalse(Config.isPerfectSquare(0));
        assertFalse(Config.isPerfectSquare(-4));
        assertFalse(Config.isPerfectSquare(2));
        assertFalse(Config.isPerfectSquare(15));
    }

    @Test
    void anImageLargerThanTheLimitIsRefusedWhereItsSizeIsSet() {
        // 7680 x 4320 = 33,177,600 pixels is the default limit; one more row is too many, 7680 pixels
        // more, which megapixels to one decimal would round away (33.2 and 33.2): so the pixels are shown
        assertSizeError("config.properties:2:1: display_width x display_height: 7680x4321 is 33,185,280 pixels; "
                + "the largest image allowed is 33,177,600 pixels (config key max_image_pixels)",
                "display_height=4321\ndisplay_width=7680\n");
        assertSizeError("config.properties:2:1: display_width x display_height: 7680x4400 is 33.8 megapixels; "
                + "the largest image allowed is 33.2 megapixels (config key max_image_pixels)",
                "display_height=4400\ndisplay_width=7680\n");
    }

    /**
     * One order: defaults, config, block, flags, then the limits on the result. A config whose own size breaks
     * its own limit loads; a render: block's size or --width and --height in its place are what is checked.
     */
    @Test
    void aConfigsSizeBeyondItsLimitYieldsToABlockOrFlagsThatSetAnother() throws InputException {
        Config config = parse("display_width=20000\ndisplay_height=20000\n");
        Flags size = new Flags(100, 80, null, null, null, null);
        assertEquals(100, size.effective(config, glint.scene.RenderBlock.NONE).displayWidth());
        assertEquals(80, size.effective(config, glint.scene.RenderBlock.NONE).displayHeight());
        glint.scene.RenderBlock block = glint.scenefile.SceneLoader.parse("s.yaml",
                "render: {width: 64, height: 48}\n").render();
        assertEquals(64, Flags.NONE.effective(config, block).displayWidth());
        assertSizeError("config.properties:1:1: display_width x display_height: 20000x20000 is 400.0 megapixels; "
                + "the largest image allowed is 33.2 megapixels (config key max_image_pixels)",
                "display_width=20000\ndisplay_height=20000\n");
    }

    @Test
    void aLimitLoweredBelowTheDefaultDepthLowersTheDepth() throws InputException {
        assertEquals(8, parse("max_recursion=8\n").recursionMax());
        assertEquals(3, parse("max_recursion=8\nrecursion_max=3\n").recursionMax());
    }

    @Test
    void aLimitLoweredBelowTheDefaultImageIsRefusedAtTheLimit() {
        assertSizeError("config.properties:2:1: display_width x display_height: 800x600 is 0.5 megapixels; "
                + "the largest image allowed is 0.0 megapixels (config key max_image_pixels)",
                "threads=1\nmax_image_pixels=100\n");
    }

    @Test
    void recursionBeyondTheLimitIsRefused() {
        assertError("config.properties:2:1: recursion_max: expected a whole number from 1 to 10, got '11'",
                "max_recursion=10\nrecursion_max=11\n");
    }

    @Test
    void aMillionPixelWideImageIsRefused() {
        assertError("config.properties:1:1: display_width: expected a whole number from 1 to 65536, got '1000000'",
                "display_width=1000000\n");
    }

    // ---------------------------------------------------------------- hostile input

    @Test
    void digitsOfOtherScriptsAreNotNumbers() {
        // Arabic-Indic three and sixteen: Java's Integer.parseInt would take them
        assertError("config.properties:1:1: threads: expected a whole number from 0 to 1024, got '\u0663'",
                "threads=\u0663\n");
        assertError("config.properties:1:1: samples: expected a whole number from 1 to 4096, got '\u0661\u0666'",
                "samples=\u0661\u0666\n");
        assertError("config.properties:1:1: epsilon: expected a positive number, got '0x1p-30'", "epsilon=0x1p-30\n");
    }

    @Test
    void aKeyWrittenAcrossAContinuationKeepsItsLineAndColumn() {
        // "thre\" + "  ads=x" is the key "threads" on line 2, column 3
        assertError("config.properties:2:3: threads: expected a whole number from 0 to 1024, got 'x'",
                "debug=false\n  thre\\\n    ads=x\n");
    }

    @Test
    void aKeyWrittenWithAUnicodeEscapeKeepsItsLineAndColumn() {
        // the escape of the letter t: the key is "threads", on line 3, column 1
        assertError("config.properties:3:1: threads: expected a whole number from 0 to 1024, got 'x'",
                "# c\n\n\\u0074hreads=x\n");
    }

    @Test
    void aValueContinuedOnTheNextLineIsJoined() throws InputException {
        assertEquals("My Glint", parse("name=My \\\n    Glint\n").name());
    }

    @Test
    void escapesAndNewlinesInAKeyAreShownEscaped() {
        // a key holding a line break and a terminal escape: one line, nothing the terminal acts on
        assertError("config.properties:1:1: unknown key 'a\\nb\\u001b[2J' (expected one of: debug, epsilon, "
                + "display_scale, screen_divider, display_height, recursion_max, display_width, name, scene, threads, "
                + "shading, integrator, samples, noise, max_samples, min_weight, move_speed, turn_speed, target_fps, free_flight, exposure, tone, "
                + "max_image_pixels, "
                + "max_scene_bytes, max_objects, max_lights, max_recursion)", "a\\nb\u001b[2J=1\n");
    }

    @Test
    void imagePixelsAboveWhatAnArrayHoldsAreRefused() {
        // 3 floats a pixel in one Java array: at most (2^31 - 9) / 3 = 715,827,879 pixels
        assertError("config.properties:1:1: max_image_pixels: expected a whole number from 1 to 700000000, "
                + "got '2147483648'", "max_image_pixels=2147483648\n");
    }

    @Test
    void recursionLimitsStopAt64() throws InputException {
        assertError("config.properties:1:1: max_recursion: expected a whole number from 1 to 64, got '1024'",
                "max_recursion=1024\n");
        assertEquals(64, parse("recursion_max=64\n").recursionMax(), "the default limit allows 64");
        assertError("config.properties:2:1: recursion_max: expected a whole number from 1 to 8, got '9'",
                "max_recursion=8\nrecursion_max=9\n");
    }

    @Test
    void aBinaryConfigSaysWhereAndWhy(@TempDir Path dir) throws IOException {
        Path binary = Files.write(dir.resolve("b.properties"), new byte[] {'a', '=', '1', '\n', (byte) 0xC3, '('});
        InputException e = assertThrows(InputException.class, () -> ConfigLoader.load(binary));
        // 0xC3 starts a two-byte character that '(' cannot continue: line 2, column 1
        assertEquals(binary + ":2:1: not UTF-8 text: byte 0xC3 cannot stand here in UTF-8 (save the file as UTF-8)",
                e.getMessage());
        Path utf16 = Files.write(dir.resolve("u.properties"), "threads=2\n".getBytes(java.nio.charset.StandardCharsets.UTF_16LE));
        e = assertThrows(InputException.class, () -> ConfigLoader.load(utf16));
        assertEquals(utf16 + ":1:1: not UTF-8 text: the file looks like UTF-16 (save it as UTF-8)", e.getMessage());
    }

    @Test
    void aConfigSavedAsUtf8WithAByteOrderMarkIsRead(@TempDir Path dir) throws IOException, InputException {
        byte[] bom = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};
        Path file = dir.resolve("bom.properties");
        Files.write(file, bom);
        Files.writeString(file, "threads=3\nsamples=9\n", java.nio.file.StandardOpenOption.APPEND);
        Config c = ConfigLoader.load(file);
        assertEquals(3, c.threads());
        assertEquals(9, c.samples());
        // a mistake on its first line is at column 1, the mark not counted
        Files.write(file, bom);
        Files.writeString(file, "threds=3\n", java.nio.file.StandardOpenOption.APPEND);
        InputException e = assertThrows(InputException.class, () -> ConfigLoader.load(file));
        assertEquals(file + ":1:1: unknown key 'threds' (did you mean 'threads'?)", e.getMessage());
    }

    @Test
    void columnsCountCharactersNotUtf16Units() {
        // "name=😀😀" is 7 characters (9 UTF-16 units): the escape starts at column 8
        assertError("config.properties:1:8: a \\u escape needs four hex digits, as in \\u00e9", "name=😀😀\\uZZZZ\n");
    }

    @Test
    void aUtf32ConfigIsNamedUtf32(@TempDir Path dir) throws IOException {
        Path utf32 = Files.write(dir.resolve("u.properties"), "threads=2\n".getBytes(java.nio.charset.Charset.forName("UTF-32")));
        InputException e = assertThrows(InputException.class, () -> ConfigLoader.load(utf32));
        assertEquals(utf32 + ":1:1: not UTF-8 text: the file looks like UTF-32 (save it as UTF-8)", e.getMessage());
        Path littleEndian = Files.write(dir.resolve("le.properties"),
                "threads=2\n".getBytes(java.nio.charset.Charset.forName("UTF-32LE")));
        e = assertThrows(InputException.class, () -> ConfigLoader.load(littleEndian));
        assertEquals(littleEndian + ":1:1: not UTF-8 text: the file looks like UTF-32 (save it as UTF-8)", e.getMessage());
    }

    @Test
    void theKeysTableOfConfigMdListsEveryKeyInOrder() throws IOException {
        // the message for an unknown key lists KEYS; config.md says it lists the table's keys
        List<String> documented = Files.readAllLines(Path.of("docs/config.md")).stream()
                .dropWhile(line -> !line.equals("## Keys"))
                .filter(line -> line.startsWith("| `"))
                .takeWhile(line -> line.startsWith("| `"))
                .map(line -> line.substring(3, line.indexOf('`', 3)))
                .toList();
        assertEquals(List.copyOf(ConfigLoader.KEYS), documented);
    }

    @Test
    void aFifoOrDeviceAsConfigIsRefusedWithoutOpeningIt(@TempDir Path dir) throws Exception {
        Path fifo = dir.resolve("fifo.properties");
        assertEquals(0, new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor());
        InputException e = assertTimeoutPreemptively(java.time.Duration.ofSeconds(20),
                () -> assertThrows(InputException.class, () -> ConfigLoader.load(fifo)));
        assertEquals(fifo + ": is not a regular file (a pipe, device or socket); expected a file on disk", e.getMessage());
        e = assertThrows(InputException.class, () -> ConfigLoader.load(Path.of("/dev/zero")));
        assertEquals("/dev/zero: is not a regular file (a pipe, device or socket); expected a file on disk", e.getMessage());
    }

    @Test
    void aConfigLargerThanOneMegabyteIsRefusedByItsSize(@TempDir Path dir) throws IOException {
        Path big = Files.writeString(dir.resolve("big.properties"), "#" + "x".repeat(1 << 20) + "\n");
        InputException e = assertThrows(InputException.class, () -> ConfigLoader.load(big));
        // "#", 2^20 x "x", "\n": 1,048,578 bytes, in bytes since both round to 1.0 MB
        assertEquals(big + ": the file is 1,048,578 bytes; the largest config file accepted is 1,048,576 bytes",
                e.getMessage());
    }
}
