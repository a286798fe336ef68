package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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
 * Ctrl-C during a long still: the real program in its own JVM, sent SIGINT once it shows progress,
 * stops with status 130, one line, no stack trace, and no image or temporary file left.
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
        Path status = Path.of("/proc/self/status");
        if (!Files.exists(status)) {
            return false;
        }
        for (String line : Files.readAllLines(status)) {
            if (line.startsWith("SigIgn:")) {
                return (Long.parseLong(line.substring(7).trim(), 16) & (1L << 1)) != 0; // bit of signal 2
            }
        }
        return false;
    }

    @Test
    void ctrlCStopsALongStillAtOnceWithNoImageLeft() throws Exception {
        assumeFalse(sigintIgnored(), "SIGINT is ignored in this process and so in its children");
        Path output = dir.resolve("long.png");
        Path config = Files.writeString(dir.resolve("empty.properties"), "");
        // 1 thread, 400 x 300 at 1,024 samples: minutes of work, so it is still rendering when stopped
        ProcessBuilder builder = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", classPath(), "glint.app.Main", "--config", config.toString(), "--scene",
                Path.of("scenes/default.yaml").toAbsolutePath().toString(), "--output", output.toString(),
                "--width", "400", "--height", "300", "--spp", "1024", "--threads", "1");
        builder.redirectOutput(dir.resolve("out.txt").toFile());
        Process process = builder.start();
        List<String> err = new ArrayList<>();
        assertTimeoutPreemptively(Duration.ofSeconds(120), () -> {
            try (BufferedReader lines = new BufferedReader(
                    new InputStreamReader(process.getErrorStream(), StandardCharsets.UTF_8))) {
                String line = lines.readLine(); // blocks until the first progress line, after about 2 s
                err.add(line);
                assertTrue(line != null && line.startsWith("rendering: "), String.valueOf(line));
                Process kill = new ProcessBuilder("kill", "-INT", Long.toString(process.pid())).start();
                assertEquals(0, kill.waitFor());
                for (line = lines.readLine(); line != null; line = lines.readLine()) {
                    err.add(line);
                }
            }
            assertEquals(130, process.waitFor(), err.toString());
        });
        assertEquals("glint: interrupted; no image written", err.get(err.size() - 1), err.toString());
        assertFalse(err.stream().anyMatch(l -> l.contains("Exception") || l.contains("\tat ")), err.toString());
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of("empty.properties", "out.txt"),
                    files.map(p -> p.getFileName().toString()).sorted().toList(), "no image, no temporary file");
        }
    }
}
