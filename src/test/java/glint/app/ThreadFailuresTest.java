package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedWriter;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every thread of the program ends in one line: memory running out in the progress thread, or any
 * thread's error, is {@code glint: ...} on standard error and status 1, never a stack trace; memory
 * running out is said once, whichever thread meets it first.
 */
class ThreadFailuresTest {

    @TempDir
    Path dir;

    private final StringWriter text = new StringWriter();
    private final PrintWriter err = new PrintWriter(text, true);

    private static void runAndJoin(String name, Runnable task, ThreadFailures failures) throws InterruptedException {
        Thread t = new Thread(task, name);
        t.setUncaughtExceptionHandler(failures::uncaught); // as the default handler main installs
        t.start();
        t.join();
    }

    @Test
    void memoryRunningOutInTwoThreadsAndMainIsOneLineAndStatus1() throws Exception {
        ThreadFailures failures = new ThreadFailures(err);
        runAndJoin("glint-progress", () -> {
            throw new OutOfMemoryError("Java heap space");
        }, failures);
        runAndJoin("glint-tracer-1", () -> {
            throw new OutOfMemoryError("Java heap space");
        }, failures);
        failures.outOfMemory(new OutOfMemoryError("Java heap space")); // the main thread's own
        assertEquals(Main.outOfMemory(new OutOfMemoryError("Java heap space")) + "\n", text.toString());
        assertEquals(Main.FAILURE, failures.status(Main.OK));
    }

    @Test
    void anotherThreadsErrorIsOneLineNamingItAndStatus1() throws Exception {
        ThreadFailures failures = new ThreadFailures(err);
        runAndJoin("glint-scene-watcher", () -> {
            throw new IllegalStateException("no such state");
        }, failures);
        assertEquals("glint: unexpected error on glint-scene-watcher: java.lang.IllegalStateException: no such state\n",
                text.toString());
        assertEquals(Main.FAILURE, failures.status(Main.OK));
        assertEquals(Main.BAD_INPUT, failures.status(Main.BAD_INPUT), "a status that already says failure stays");
    }

    @Test
    void aRunWithNoThreadFailureKeepsItsStatus() {
        ThreadFailures failures = new ThreadFailures(err);
        assertEquals(Main.OK, failures.status(Main.OK));
        assertEquals("", text.toString());
    }

    /** The progress thread itself, on its real timer: memory running out while it reads the progress. */
    @Test
    void theProgressThreadRunningOutOfMemoryEndsInTheOneLine() throws Exception {
        ThreadFailures failures = new ThreadFailures(err);
        Thread.UncaughtExceptionHandler before = Thread.getDefaultUncaughtExceptionHandler();
        Thread.setDefaultUncaughtExceptionHandler(failures::uncaught);
        try (Progress progress = Progress.start(err)) {
            progress.step("rendering", () -> {
                throw new OutOfMemoryError("Java heap space");
            });
            assertTimeoutPreemptively(Duration.ofSeconds(30), () -> {
                while (!text.toString().contains("\n")) { // a bounded poll: the first read comes after 2 quiet seconds
                    Thread.sleep(5);
                }
            });
        } finally {
            Thread.setDefaultUncaughtExceptionHandler(before);
        }
        assertEquals(Main.outOfMemory(new OutOfMemoryError("Java heap space")) + "\n", text.toString());
        assertEquals(Main.FAILURE, failures.status(Main.OK));
    }

    /**
     * As a user meets it: {@code java -Xmx64m ... --scene many.yaml --output m.png}, 100,000 spheres (within
     * every limit), four times (the progress thread ran out of memory in some runs, not others). Each run
     * ends in its progress lines and the one out-of-memory line, status 1.
     */
    @Test
    void aSceneTooLargeForTheHeapEndsInOneLineInEveryRun() throws Exception {
        Path scene = dir.resolve("many.yaml");
        Random random = new Random(7);
        try (BufferedWriter w = Files.newBufferedWriter(scene)) {
            w.write("camera: {position: [0, 5, -30], look_at: [0, 0, 0]}\nlights:\n  - {type: point, position: [0, 20, -10]}\n");
            w.write("objects:\n");
            for (int i = 0; i < 100_000; i++) {
                w.write(String.format(Locale.ROOT, "  - {type: sphere, center: [%.3f, %.3f, %.3f], radius: 0.05}%n",
                        random.nextDouble() * 20 - 10, random.nextDouble() * 10, random.nextDouble() * 20 - 10));
            }
        }
        Path config = Files.writeString(dir.resolve("empty.properties"), "");
        List<String> command = new ArrayList<>(Child.java("-Xmx64m"));
        command.addAll(List.of("--config", config.toString(), "--scene", scene.toString(), "--output",
                dir.resolve("m.png").toString(), "--width", "64", "--height", "48"));
        for (int run = 1; run <= 4; run++) {
            Child.Result r = Child.sh(dir, Child.line(command) + "\n", java.util.Map.of());
            String all = r.err() + r.out();
            assertEquals(Main.FAILURE, r.status(), all);
            assertFalse(all.contains("Exception") || all.contains("\tat "), "run " + run + ":\n" + all);
            List<String> lines = r.err().lines().toList();
            assertTrue(lines.get(lines.size() - 1).startsWith("glint: out of memory ("), all);
            for (String line : lines.subList(0, lines.size() - 1)) {
                assertTrue(line.matches("(reading|preparing) the scene\\.\\.\\.( [0-9]+ s so far)?"), all);
            }
            assertFalse(Files.exists(dir.resolve("m.png")));
        }
    }

    /**
     * Memory running out in a render thread between its tasks, as a bidirectional still far too large for
     * the heap makes it do, ends the run like any other: one line, status 1, no image. The shell's
     * {@code timeout} only turns a hang into a failed status.
     */
    @Test
    void aBidirectionalStillTooLargeForTheHeapEndsAndNeverHangs() throws Exception {
        Path scene = Path.of("scenes/caustics.yaml").toAbsolutePath();
        Path config = Files.writeString(dir.resolve("empty.properties"), "");
        List<String> command = new ArrayList<>(List.of("timeout", "-s", "KILL", "300"));
        command.addAll(Child.java("-Xmx48m"));
        command.addAll(List.of("--config", config.toString(), "--scene", scene.toString(), "--integrator", "bdpt",
                "--width", "320", "--height", "240", "--spp", "4", "--output", dir.resolve("b.png").toString()));
        for (int run = 1; run <= 3; run++) {
            Child.Result r = Child.sh(dir, Child.line(command) + "\n", java.util.Map.of());
            String all = r.err() + r.out();
            assertEquals(Main.FAILURE, r.status(), "run " + run + ":\n" + all);
            assertFalse(all.contains("Exception") || all.contains("\tat "), "run " + run + ":\n" + all);
            List<String> lines = r.err().lines().toList();
            assertEquals(1, lines.stream().filter(l -> l.startsWith("glint: out of memory (")).count(), all);
            for (String line : lines) {
                assertTrue(line.startsWith("glint: out of memory (")
                        || line.matches("(reading|preparing) the scene\\.\\.\\.( [0-9]+ s so far)?|rendering: .*")
                        || line.equals("glint: the program ended before the image was written; nothing written, its "
                                + "hidden temporary file removed"), all);
            }
            assertFalse(Files.exists(dir.resolve("b.png")));
        }
    }
}
