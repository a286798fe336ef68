package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedReader;
import java.io.File;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Standard output that fails, as a Unix tool meets it: the real program in its own JVM, its standard
 * output a full device (/dev/full), a closed descriptor ({@code >&-}), or a pipe whose reader has gone
 * ({@code | head -1}). A write error is one line on standard error and status 1; a reader that has gone
 * stops the work at the next line, quietly, with status 141 (128 + SIGPIPE), as {@code yes | head -1}.
 */
class StandardOutputTest {

    private static final String SCENE = """
            camera: {position: [0, 1, -4], look_at: [0, 1, 0]}
            lights:
              - {type: point, position: [-3, 5, -4], intensity: 50}
            objects:
              - {type: sphere, center: [0, 1, 0], radius: 1}
              - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
            """;

    @TempDir
    Path dir;
    private Path scene;

    @BeforeEach
    void files() throws Exception {
        Files.writeString(dir.resolve("empty.properties"), "");
        scene = Files.writeString(dir.resolve("scene.yaml"), SCENE);
    }

    private List<String> command(String... args) throws Exception {
        List<String> command = new ArrayList<>(Child.java());
        command.addAll(List.of("--config", dir.resolve("empty.properties").toString()));
        command.addAll(List.of(args));
        return command;
    }

    /** Runs the program with its standard output going to {@code device}. */
    private Child.Result toDevice(String device, String... args) throws Exception {
        assumeTrue(Files.exists(Path.of(device)), device + " exists here");
        return Child.sh(dir, Child.line(command(args)) + " >" + device + "\n", Map.of());
    }

    private static void assertOneLine(String line, Child.Result r) {
        assertEquals(Main.FAILURE, r.status(), r::toString);
        assertEquals(line + "\n", r.err(), r::toString);
    }

    @Test
    void benchToAFullDiskSaysSoWithStatus1() throws Exception {
        Child.Result r = toDevice("/dev/full", "--scene", scene.toString(), "--bench", "3", "--width", "32",
                "--height", "24");
        assertOneLine("glint: cannot write to standard output: No space left on device", r);
    }

    @Test
    void benchWithStandardOutputClosedSaysSoWithStatus1() throws Exception {
        Child.Result r = Child.sh(dir, Child.line(command("--scene", scene.toString(), "--bench", "3", "--width", "32",
                "--height", "24")) + " >&-\n", Map.of());
        assertOneLine("glint: cannot write to standard output: Bad file descriptor", r);
    }

    @Test
    void helpAndVersionToAFullDiskSaySoWithStatus1() throws Exception {
        assertOneLine("glint: cannot write to standard output: No space left on device", toDevice("/dev/full", "--help"));
        assertOneLine("glint: cannot write to standard output: No space left on device", toDevice("/dev/full", "--version"));
    }

    /** The image is written; the line saying so is what failed, and the message says the image is there. */
    @Test
    void aStillWhoseReportCannotBeWrittenSaysTheImageWasWritten() throws Exception {
        Path png = dir.resolve("out.png");
        Child.Result r = toDevice("/dev/full", "--scene", scene.toString(), "--output", png.toString(), "--width", "32",
                "--height", "24");
        assertOneLine("glint: cannot write to standard output: No space left on device (" + png + " was written)", r);
        assertEquals(32, ImageIO.read(png.toFile()).getWidth());
    }

    /**
     * {@code --bench 100000 | head -2}: once the reader has taken its lines and gone, the next frame's line
     * meets the closed pipe and the program ends there, status 141 and nothing on standard error. Without
     * it the 100,000 frames would take far longer than the guard allows.
     */
    @Test
    void benchIntoAPipeWhoseReaderHasGoneStopsAtTheNextFrame() throws Exception {
        ProcessBuilder builder = new ProcessBuilder(command("--scene", scene.toString(), "--bench", "100000",
                "--width", "64", "--height", "48", "--spp", "16"));
        File err = dir.resolve("err.txt").toFile();
        builder.redirectError(err);
        Process process = builder.start();
        assertTimeoutPreemptively(Duration.ofSeconds(120), () -> {
            try (BufferedReader lines = new BufferedReader(new InputStreamReader(process.getInputStream(),
                    StandardCharsets.UTF_8))) {
                String heading = lines.readLine();
                assertTrue(heading != null && heading.startsWith("timing 100000 frames of "), heading);
                String first = lines.readLine();
                assertTrue(first != null && first.startsWith("frame 1: "), first);
            } // head -2 has its lines and exits: the pipe's only reader is closed
            assertEquals(Main.READER_GONE, process.waitFor());
        }, () -> {
            process.destroyForcibly();
            return "still rendering after its reader had gone";
        });
        assertEquals("", Files.readString(err.toPath()));
    }

    /** {@code --help | true}: the reader is gone before the first line; quiet, status 141. */
    @Test
    void helpIntoAPipeWithNoReaderEndsQuietly() throws Exception {
        ProcessBuilder builder = new ProcessBuilder(command("--help"));
        File err = dir.resolve("err.txt").toFile();
        builder.redirectError(err);
        Process process = builder.start();
        process.getInputStream().close(); // long before the JVM has started and printed anything
        assertEquals(Main.READER_GONE, process.waitFor());
        assertEquals("", Files.readString(err.toPath()));
    }
}
