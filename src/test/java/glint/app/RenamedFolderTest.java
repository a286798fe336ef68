package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
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
 * The output's folder renamed while the still renders (the hidden temporary file is made in it before
 * the work): the image cannot be put where it was asked for, and the folder, wherever it is now, keeps
 * nothing, not even an empty {@code .long.png.<n>.part}. The real program in its own JVM, the folder
 * renamed once it shows the render's progress.
 */
class RenamedFolderTest {

    @TempDir
    Path dir;

    /** Starts the render into {@code out/long.png}, renames {@code out} at its first progress line, and returns its stderr and status. */
    private List<String> renderAndRename(boolean thenStop) throws Exception {
        Path out = Files.createDirectory(dir.resolve("out"));
        Path config = Files.writeString(dir.resolve("empty.properties"), "");
        List<String> command = new ArrayList<>(Child.java());
        // 1 thread, 320 x 240 at 256 samples: seconds of work, so the progress line comes while it renders
        command.addAll(List.of("--config", config.toString(), "--scene", Path.of("scenes/default.yaml").toAbsolutePath()
                .toString(), "--output", out.resolve("long.png").toString(), "--width", "320", "--height", "240", "--spp",
                "256", "--threads", "1"));
        Process process = new ProcessBuilder(command).redirectOutput(dir.resolve("stdout.txt").toFile()).start();
        List<String> err = new ArrayList<>();
        assertTimeoutPreemptively(Duration.ofSeconds(180), () -> {
            try (BufferedReader lines = new BufferedReader(new InputStreamReader(process.getErrorStream(),
                    StandardCharsets.UTF_8))) {
                String line;
                do {
                    line = lines.readLine();
                    err.add(line);
                } while (line != null && !line.startsWith("rendering: "));
                assertTrue(line != null, err.toString());
                try (Stream<Path> files = Files.list(out)) {
                    assertEquals(1, files.filter(p -> p.getFileName().toString().endsWith(".part")).count(),
                            "the temporary file is there before the work");
                }
                Files.move(out, dir.resolve("moved"));
                if (thenStop) {
                    assertEquals(0, new ProcessBuilder("kill", "-TERM", Long.toString(process.pid())).start().waitFor());
                }
                for (line = lines.readLine(); line != null; line = lines.readLine()) {
                    err.add(line);
                }
            }
            err.add(Integer.toString(process.waitFor()));
        });
        return err;
    }

    private void assertNothingLeft() throws Exception {
        try (Stream<Path> files = Files.list(dir.resolve("moved"))) {
            assertEquals(List.of(), files.toList(), "the renamed folder keeps nothing");
        }
        assertEquals("", Files.readString(dir.resolve("stdout.txt")), "nothing says the image was written");
    }

    @Test
    void aFolderRenamedDuringTheRenderKeepsNoTemporaryFile() throws Exception {
        List<String> err = renderAndRename(false);
        assertEquals(Main.FAILURE, Integer.parseInt(err.remove(err.size() - 1)), err.toString());
        assertEquals("glint: cannot write " + dir.resolve("out/long.png") + ": No such file or directory",
                err.get(err.size() - 1), err.toString());
        assertNothingLeft();
    }

    @Test
    void aFolderRenamedAndThenTheRunStoppedKeepsNoTemporaryFile() throws Exception {
        List<String> err = renderAndRename(true);
        assertEquals(143, Integer.parseInt(err.remove(err.size() - 1)), err.toString());
        assertEquals("glint: interrupted; no image written", err.get(err.size() - 1), err.toString());
        assertNothingLeft();
    }
}
