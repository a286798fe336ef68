package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every file of the malformed-input corpus (src/test/resources/malformed, expectations in its
 * expected.tsv) is refused with its exact message, status 2 and no stack trace, and never hangs.
 */
class MalformedCorpusTest {

    private static final Path CORPUS = Path.of("src/test/resources/malformed");
    /**
     * A guard against hangs, not a speed requirement: a hang never ends, while the scene of 100,001
     * objects took 17-22 s on 2 cores shared with other builds (load average 9.7).
     */
    private static final Duration HANG_GUARD = Duration.ofSeconds(60);

    @TempDir
    Path dir;

    record Expectation(String file, String message) {
        @Override
        public String toString() {
            return file;
        }
    }

    static Stream<Expectation> corpus() throws IOException {
        return Files.readAllLines(CORPUS.resolve("expected.tsv"), StandardCharsets.UTF_8).stream()
                .filter(line -> !line.startsWith("#") && !line.isBlank())
                .map(line -> line.split("\t", 2))
                .map(parts -> new Expectation(parts[0], parts[1]));
    }

    @Test
    void theCorpusHasAtLeastFortyInputs() throws IOException {
        assertTrue(corpus().count() >= 40);
    }

    @ParameterizedTest
    @MethodSource("corpus")
    void eachMalformedSceneGetsItsExactMessage(Expectation expectation) {
        Path scene = CORPUS.resolve(expectation.file());
        String firstLine = refused(scene);
        if (expectation.message().equals("*")) {
            assertTrue(firstLine.startsWith(scene + ":"), firstLine);
            assertTrue(firstLine.contains("YAML"), firstLine);
        } else if (expectation.message().startsWith("0:0: ")) {
            assertEquals(scene + ": " + expectation.message().substring(5), firstLine);
        } else {
            assertEquals(scene + ":" + expectation.message(), firstLine);
        }
    }

    @Test
    void aFiftyMegabyteSceneIsRefusedBeforeItIsRead() throws IOException {
        Path big = dir.resolve("big.yaml");
        byte[] line = "  - {type: sphere, center: [0, 0, 0], radius: 1}\n".getBytes(StandardCharsets.US_ASCII);
        try (var out = Files.newOutputStream(big)) {
            out.write("objects:\n".getBytes(StandardCharsets.US_ASCII));
            for (long written = 0; written < 50L * 1024 * 1024; written += line.length) {
                out.write(line);
            }
        }
        String expected = String.format(java.util.Locale.ROOT,
                "%s: the file is %.1f MB; the largest scene accepted is 8.0 MB (config key max_scene_bytes)",
                big, Files.size(big) / 1048576.0);
        assertEquals(expected, refused(big));
    }

    @Test
    void moreObjectsThanTheLimitAreRefusedAtTheFirstOneTooMany() throws IOException {
        Path many = dir.resolve("many.yaml");
        StringBuilder text = new StringBuilder("objects:\n");
        for (int i = 0; i < 100_001; i++) {
            text.append("  - {type: sphere, center: [0, 0, ").append(i).append("], radius: 0.1}\n");
        }
        Files.writeString(many, text);
        // line 1 is "objects:", object k (from 1) is on line k + 1
        assertEquals(many + ":100002:5: too many objects: more than 100000 (config key max_objects)", refused(many));
    }

    @Test
    void aFifoAsSceneIsRefusedWithoutOpeningIt() throws Exception {
        Path fifo = dir.resolve("scene.yaml");
        assertEquals(0, new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor(), "mkfifo");
        // opened for reading, a FIFO would block until a writer came: the hang guard would fail
        assertEquals(fifo + ": is not a regular file (a pipe, device or socket); expected a file on disk", refused(fifo));
    }

    @Test
    void devicesAsSceneAreRefusedWithoutReadingThem() {
        // /dev/zero and /dev/urandom never end: read whole, they exhaust the heap
        for (String device : List.of("/dev/zero", "/dev/urandom")) {
            assertEquals(device + ": is not a regular file (a pipe, device or socket); expected a file on disk",
                    refused(Path.of(device)));
        }
    }

    @Test
    void aLineOfEightMegabytesIsRefusedAtOnce() throws IOException {
        // under the 8 MiB size limit, but the YAML reader's time grows with the square of a line's length
        Path longLine = dir.resolve("long.yaml");
        int length = 8 * 1024 * 1024 - 100;
        Files.writeString(longLine, "objects: []\n#" + "x".repeat(length - 1) + "\n");
        assertEquals(longLine + ":2:65537: line 2 is 8,388,508 characters long; the longest line accepted is 65,536 "
                + "(break it into shorter lines)", refused(longLine));
    }

    @Test
    void aKeyOfALongLineIsRefusedToo() throws IOException {
        Path longKey = dir.resolve("key.yaml");
        Files.writeString(longKey, "k".repeat(65_537) + ": 1\n");
        assertEquals(longKey + ":1:65537: line 1 is 65,540 characters long; the longest line accepted is 65,536 "
                + "(break it into shorter lines)", refused(longKey));
    }

    /** Runs a headless render of the scene and returns the first line it printed to stderr after any progress. */
    private String refused(Path scene) {
        return assertTimeoutPreemptively(HANG_GUARD, () -> {
            StringWriter out = new StringWriter(), err = new StringWriter();
            int status = Main.run(new String[] {"--scene", scene.toString(), "--output",
                    dir.resolve("never.png").toString(), "--width", "8", "--height", "6"},
                    new PrintWriter(out, true), new PrintWriter(err, true));
            String text = err.toString();
            assertEquals(2, status, text);
            assertFalse(text.contains("Exception") || text.contains("\tat "), text);
            assertFalse(Files.exists(dir.resolve("never.png")), "no image is written");
            // a scene that takes seconds to read shows that step first ("reading the scene...")
            List<String> lines = text.lines().filter(l -> !l.matches("(reading|preparing) the scene\\.\\.\\.( [0-9]+ s so far)?")).toList();
            return lines.isEmpty() ? "" : lines.get(0);
        });
    }
}
