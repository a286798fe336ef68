package glint.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.io.BufferedReader;
import java.io.File;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Signals during a long still: the real program in its own JVM, sent SIGINT, SIGTERM or SIGHUP once
 * it shows progress, stops with status 128 + the signal's number, one line, no stack trace, and no
 * image or temporary file left; stopped while writing, it keeps the image that was there.
 */
class InterruptTest {

    @TempDir
    Path dir;

    /** target/classes and the jars the program needs, wherever the build put them. */
    private static String classPath() throws Exception {
        List<String> parts = new ArrayList<>();
        for (Class<?> c : List.of(Main.class, picocli.CommandLine.class, org.snakeyaml.engine.v2.api.LoadSettings.class)) {
            parts.add(Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI()).toString());
        }
        return String.join(File.pathSeparator, parts);
    }

    /** True when this JVM was started with SIGINT ignored (a background job of a script): its child would be too. */
    private static boolean sigintIgnored() throws Exception {
        return ignored(2);
    }

    /** True when this JVM was started with the signal ignored (SIGHUP under nohup): its child would be too. */
    private static boolean ignored(int signal) throws Exception {
        Path status = Path.of("/proc/self/status");
        if (!Files.exists(status)) {
            return false;
        }
        for (String line : Files.readAllLines(status)) {
            if (line.startsWith("SigIgn:")) {
                return (Long.parseLong(line.substring(7).trim(), 16) & (1L << (signal - 1))) != 0;
            }
        }
        return false;
    }

    @Test
    void ctrlCStopsALongStillAtOnceWithNoImageLeft() throws Exception {
        assumeFalse(sigintIgnored(), "SIGINT is ignored in this process and so in its children");
        stopWhileRendering("INT", 130);
    }

    /** SIGTERM (kill, timeout, a service manager) exits with the conventional 128 + 15. */
    @Test
    void sigtermStopsALongStillTheSameWayWithStatus143() throws Exception {
        stopWhileRendering("TERM", 143);
    }

    /** SIGHUP (the terminal closed, an ssh session lost) exits with 128 + 1. */
    @Test
    void sighupStopsALongStillTheSameWayWithStatus129() throws Exception {
        assumeFalse(ignored(1), "SIGHUP is ignored in this process (nohup) and so in its children");
        stopWhileRendering("HUP", 129);
    }

    /** SIGUSR1 (or SIGALRM, ...), which would end the JVM without its hooks, stops it the same way: 128 + 10. */
    @Test
    void sigusr1StopsALongStillTheSameWayWithStatus138() throws Exception {
        assumeFalse(ignored(10), "SIGUSR1 is ignored in this process and so in its children");
        stopWhileRendering("USR1", 138);
    }

    /** SIGSTKFLT, SIGSYS and SIGTRAP, whose default would end the JVM at once, stop it the same way: 144, 159, 133. */
    @Test
    void sigstkfltSigsysAndSigtrapStopALongStillTheSameWay() throws Exception {
        for (String signal : List.of("STKFLT", "SYS", "TRAP")) {
            int number = switch (signal) {
                case "STKFLT" -> 16;
                case "SYS" -> 31;
                default -> 5;
            };
            assumeFalse(ignored(number), "SIG" + signal + " is ignored in this process and so in its children");
            stopWhileRendering(signal, 128 + number);
        }
    }

    private void stopWhileRendering(String signal, int status) throws Exception {
        Path output = dir.resolve("long.png");
        Path config = Files.writeString(dir.resolve("empty.properties"), "");
        // 1 thread, 400 x 300 at 1,024 samples: minutes of work, so it is still rendering when stopped
        List<String> err = stop(signal, "rendering: ", "--config", config.toString(), "--scene",
                Path.of("scenes/bench/spec-example.yaml").toAbsolutePath().toString(), "--output", output.toString(),
                "--width", "400", "--height", "300", "--spp", "1024", "--threads", "1");
        assertEquals(status, Integer.parseInt(err.remove(err.size() - 1)), err.toString());
        assertStoppedWithOneLine(err);
        assertEquals("", Files.readString(dir.resolve("out.txt")));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of("empty.properties", "out.txt"),
                    files.map(p -> p.getFileName().toString()).sorted().toList(), "no image, no temporary file");
        }
    }

    /**
     * SIGTERM while a 7680 x 4320 PNG is being encoded (seconds of work after the render): the
     * write stops, the image there before is kept byte for byte, and nothing says it was written.
     * 16 samples a pixel make the render outlast the run's first two quiet seconds, so the write's
     * progress line, which the signal waits for, is shown however fast the machine encodes.
     */
    @Test
    void sigtermWhileTheImageIsWrittenKeepsTheOldImageAndSaysSo() throws Exception {
        Path output = dir.resolve("big.png");
        byte[] old = {(byte) 0x89, 'P', 'N', 'G', 1, 2, 3};
        Files.write(output, old);
        Path config = Files.writeString(dir.resolve("empty.properties"), "");
        Path scene = Files.writeString(dir.resolve("sky.yaml"), "camera: {position: [0, 1, -4], look_at: [0, 1, 0]}\n");
        List<String> err = stop("TERM", "writing the image: ", "--config", config.toString(), "--scene", scene.toString(),
                "--output", output.toString(), "--width", "7680", "--height", "4320", "--spp", "16");
        assertEquals(143, Integer.parseInt(err.remove(err.size() - 1)), err.toString());
        assertStoppedWithOneLine(err);
        assertEquals("", Files.readString(dir.resolve("out.txt")), "no 'wrote' line");
        assertArrayEquals(old, Files.readAllBytes(output));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of("big.png", "empty.properties", "out.txt", "sky.yaml"),
                    files.map(p -> p.getFileName().toString()).sorted().toList(), "no temporary file");
        }
    }

    /**
     * SIGKILL (kill -9, the out-of-memory killer) cannot be caught: no Java code runs. The image's hidden
     * file (made before the render) is deleted all the same, by its guard outside the JVM, which says so;
     * the old image is kept.
     */
    @Test
    void sigkillLeavesNoTemporaryFileAndSaysSo() throws Exception {
        Path output = dir.resolve("long.png");
        byte[] old = {(byte) 0x89, 'P', 'N', 'G', 1, 2, 3};
        Files.write(output, old);
        Path config = Files.writeString(dir.resolve("empty.properties"), "");
        List<String> err = stop("KILL", "rendering: ", "--config", config.toString(), "--scene",
                Path.of("scenes/default.yaml").toAbsolutePath().toString(), "--output", output.toString(),
                "--width", "400", "--height", "300", "--spp", "1024", "--threads", "1");
        assertEquals(137, Integer.parseInt(err.remove(err.size() - 1)), err.toString());
        assertEquals("glint: the program ended before the image was written; nothing written, its hidden temporary "
                + "file removed", err.get(err.size() - 1), err.toString());
        assertArrayEquals(old, Files.readAllBytes(output));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of("empty.properties", "long.png", "out.txt"),
                    files.map(p -> p.getFileName().toString()).sorted().toList(), "no temporary file");
        }
    }

    /** Progress lines, then the one line that says the run was stopped: nothing else (no write failure, no trace). */
    /** --bench stopped while its scene (100,000 spheres) is read or prepared: it says so, never nothing. */
    @Test
    void sigtermWhileABenchsSceneLoadsSaysSo() throws Exception {
        StringBuilder scene = new StringBuilder("objects:\n");
        for (int i = 0; i < 100_000; i++) {
            scene.append("  - {type: sphere, center: [").append(i % 100).append(", ").append(i / 100 % 100)
                    .append(", ").append(i / 10_000).append("], radius: 0.4}\n");
        }
        Path file = Files.writeString(dir.resolve("many.yaml"), scene);
        Path config = Files.writeString(dir.resolve("empty.properties"), "");
        List<String> err = stop("TERM", "", "--config", config.toString(), "--scene", file.toString(), "--bench", "1",
                "--width", "64", "--height", "48", "--threads", "1");
        assertEquals(143, Integer.parseInt(err.remove(err.size() - 1)), err.toString());
        String last = err.get(err.size() - 1);
        assertTrue(last.equals(Headless.INTERRUPTED_BENCH) || last.equals("glint: interrupted after 0 frames"),
                err.toString());
        assertTrue(err.get(0).matches("(reading|preparing) the scene\\.\\.\\..*"), err.toString());
    }

    private static void assertStoppedWithOneLine(List<String> err) {
        assertEquals("glint: interrupted; no image written", err.get(err.size() - 1), err.toString());
        for (String line : err.subList(0, err.size() - 1)) {
            assertTrue(line.matches("(reading|preparing) the scene\\.\\.\\.( [0-9]+ s so far)?|(rendering|writing the image): [0-9]+% done, .*"),
                    err.toString());
        }
    }

    /**
     * Starts the program, sends it the signal when a line of standard error starts with
     * {@code when}, and returns the lines of standard error followed by the exit status.
     */
    private List<String> stop(String signal, String when, String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx1g", "-cp", classPath(), "glint.app.Main"));
        command.addAll(List.of(args));
        ProcessBuilder builder = new ProcessBuilder(command);
        builder.redirectOutput(dir.resolve("out.txt").toFile());
        Process process = builder.start();
        List<String> err = new ArrayList<>();
        assertTimeoutPreemptively(Duration.ofSeconds(120), () -> {
            try (BufferedReader lines = new BufferedReader(
                    new InputStreamReader(process.getErrorStream(), StandardCharsets.UTF_8))) {
                String line;
                do { // blocks until the step's first progress line, 2 s or more after the start
                    line = lines.readLine();
                    err.add(line);
                } while (line != null && !line.startsWith(when));
                assertTrue(line != null, err.toString());
                Process kill = new ProcessBuilder("kill", "-" + signal, Long.toString(process.pid())).start();
                assertEquals(0, kill.waitFor());
                for (line = lines.readLine(); line != null; line = lines.readLine()) {
                    err.add(line);
                }
            }
            err.add(Integer.toString(process.waitFor()));
        });
        return err;
    }
}
