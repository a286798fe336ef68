package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIf;
import org.junit.jupiter.api.io.TempDir;

/**
 * The window as a user runs it, in a process of its own on an X server of the test's own (Xvfb), driven by
 * a mouse and keyboard in a third process ({@link RobotOnDisplay}): a still being written when the program
 * is sent SIGTERM or SIGHUP, or when the X server dies, leaves no file and is said to be lost; a camera
 * that cannot be printed is said, and the window's exit status is 1. Skipped where there is no Xvfb.
 */
@EnabledIf("hasXvfb")
class WindowProcessTest {

    /** A still large enough that encoding and writing its PNG takes a second or more. */
    private static final String LARGE_STILL = "render: {width: 3840, height: 2160, samples: 1}\n";
    private static final String SCENE = """
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

    private Process xvfb;
    private int display;
    private Process glint;
    private BufferedReader glintErr;
    private final List<String> err = new ArrayList<>();
    private Process robot;
    private BufferedReader robotAnswers;
    private PrintWriter robotCommands;

    static boolean hasXvfb() {
        return Stream.of(System.getenv("PATH").split(File.pathSeparator))
                .anyMatch(p -> Files.isExecutable(Path.of(p, "Xvfb")));
    }

    @AfterEach
    void stopAll() {
        for (Process p : new Process[] {glint, robot, xvfb}) {
            if (p != null) {
                p.destroyForcibly();
            }
        }
    }

    /** An X server of its own; its display number once it takes connections. */
    private void startDisplay() throws IOException {
        xvfb = new ProcessBuilder("Xvfb", "-displayfd", "1", "-screen", "0", "800x600x24", "-nolisten", "tcp")
                .redirectError(ProcessBuilder.Redirect.DISCARD).start();
        String number = new BufferedReader(new InputStreamReader(xvfb.getInputStream(), StandardCharsets.US_ASCII))
                .readLine(); // written when it is ready
        assumeTrue(number != null, "Xvfb started");
        display = Integer.parseInt(number.trim());
    }

    /** The program's window on {@code scene}, its standard output to {@code stdout}; returns when it shows a frame. */
    private void startWindow(String scene, File stdout) throws Exception {
        startDisplay();
        Path config = Files.writeString(dir.resolve("window.properties"),
                "display_width=320\ndisplay_height=240\nsamples=4\nthreads=2\n");
        Path sceneFile = Files.writeString(dir.resolve("ball.yaml"), scene);
        List<String> command = new ArrayList<>(Child.java());
        command.addAll(List.of("--config", config.toString(), "--scene", sceneFile.toString()));
        ProcessBuilder builder = new ProcessBuilder(command).directory(dir.toFile()).redirectOutput(stdout);
        builder.environment().put("DISPLAY", ":" + display);
        glint = builder.start();
        glintErr = new BufferedReader(new InputStreamReader(glint.getErrorStream(), StandardCharsets.UTF_8));
        // the window is at the top left (no window manager): its middle shows the ball once a frame is on screen
        user("shown 160 120");
        user("click 160 120"); // and the click gives it the keyboard
    }

    /** Reads the program's standard error until a line starts with {@code prefix}. */
    private void awaitErrLine(String prefix) throws Exception {
        assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
            for (String line = glintErr.readLine(); ; line = glintErr.readLine()) {
                assertTrue(line != null, () -> "the program ended before '" + prefix + "': " + err);
                err.add(line);
                if (line.startsWith(prefix)) {
                    return;
                }
            }
        });
    }

    /** What the user does with the mouse or keyboard ({@link RobotOnDisplay}'s commands), once it is done. */
    private void user(String action) throws Exception {
        if (robot == null) {
            String classes = Path.of(RobotOnDisplay.class.getProtectionDomain().getCodeSource().getLocation().toURI())
                    .toString();
            ProcessBuilder builder = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-cp", classes, RobotOnDisplay.class.getName()).redirectError(ProcessBuilder.Redirect.INHERIT);
            builder.environment().put("DISPLAY", ":" + display);
            robot = builder.start();
            robotAnswers = new BufferedReader(new InputStreamReader(robot.getInputStream(), StandardCharsets.UTF_8));
            robotCommands = new PrintWriter(robot.getOutputStream(), true, StandardCharsets.UTF_8);
        }
        robotCommands.println(action);
        assertTimeoutPreemptively(Duration.ofSeconds(30), () -> assertEquals("ok", robotAnswers.readLine(), action));
    }

    /** Enter, then a bounded wait until the still's hidden PNG is being written (it has bytes). */
    private Path startLargeStillAndAwaitItsWrite() throws Exception {
        user("key ENTER");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < deadline) {
            for (Path p : files()) {
                if (p.getFileName().toString().matches("\\.ball-.*\\.png\\.[0-9a-f]+\\.part") && Files.size(p) > 0) {
                    return p;
                }
            }
            Thread.sleep(5); // a bounded poll for the file to grow
        }
        throw new AssertionError("the still's PNG is being written: not within 60 s; " + files() + "; " + err);
    }

    private List<Path> files() throws IOException {
        try (Stream<Path> list = Files.list(dir)) {
            return list.filter(p -> p.getFileName().toString().contains("ball-")).sorted().toList();
        }
    }

    /** The rest of standard error, to its end (which a guard of the still's files holds until it is done), and the status. */
    private int finish() throws Exception {
        int[] status = new int[1];
        assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
            for (String line = glintErr.readLine(); line != null; line = glintErr.readLine()) {
                err.add(line);
            }
            status[0] = glint.waitFor();
        });
        return status[0];
    }

    /** Everything standard error said. */
    private List<String> said() {
        return List.copyOf(err);
    }

    private void assertNoStackTrace() {
        assertFalse(err.stream().anyMatch(l -> l.contains("Exception") || l.startsWith("\tat ")), err::toString);
    }

    private void signalWhileALargeStillIsWritten(String signal, int status) throws Exception {
        startWindow(SCENE + LARGE_STILL, dir.resolve("stdout.txt").toFile());
        startLargeStillAndAwaitItsWrite();
        assertEquals(0, new ProcessBuilder("kill", "-" + signal, Long.toString(glint.pid())).start().waitFor());
        assertEquals(status, finish(), err::toString);
        assertEquals(List.of("glint: interrupted; still cancelled, nothing written"), said());
        assertEquals(List.of(), files(), "no image, no hidden file");
        assertEquals("", Files.readString(dir.resolve("stdout.txt")), "nothing says it was written");
    }

    @Test
    void sigtermWhileALargeStillIsWrittenStopsItAndLeavesNothing() throws Exception {
        signalWhileALargeStillIsWritten("TERM", 143);
    }

    @Test
    void sighupWhileALargeStillIsWrittenStopsItAndLeavesNothing() throws Exception {
        signalWhileALargeStillIsWritten("HUP", 129);
    }

    /**
     * The X server dies while the still is written: Xlib ends the JVM at once (status 1), where no Java code
     * runs; the still's guard deletes its hidden file and says so.
     */
    @Test
    void theXServerDyingWhileALargeStillIsWrittenLeavesNothingAndSaysSo() throws Exception {
        startWindow(SCENE + LARGE_STILL, dir.resolve("stdout.txt").toFile());
        startLargeStillAndAwaitItsWrite();
        xvfb.destroy();
        assertEquals(1, finish(), err::toString);
        assertEquals(List.of("glint: the program ended before the still was written; nothing written, its hidden "
                + "temporary file removed"), said());
        assertEquals(List.of(), files(), "no image, no hidden file");
        assertEquals("", Files.readString(dir.resolve("stdout.txt")));
    }

    /** Standard output on a full disk: key C says the camera was not printed; quitting then exits with 1. */
    @Test
    void whatTheWindowCannotPrintIsSaidAndItsExitStatusIs1() throws Exception {
        File full = new File("/dev/full");
        assumeTrue(full.exists(), "/dev/full exists here");
        startWindow(SCENE, full);
        user("key C");
        awaitErrLine("glint: camera not printed: ");
        assertEquals("glint: camera not printed: cannot write to standard output: No space left on device",
                err.get(err.size() - 1));
        user("key ESCAPE");
        assertEquals(1, finish(), err::toString);
        assertNoStackTrace();
    }

    /** A heap too small for the window (-Xmx8m): the program ends saying why, never in silence. */
    @Test
    void aWindowWithTooLittleMemorySaysWhyItEnds() throws Exception {
        startDisplay();
        Path config = Files.writeString(dir.resolve("window.properties"),
                "display_width=320\ndisplay_height=240\nsamples=4\nthreads=2\n");
        Path sceneFile = Files.writeString(dir.resolve("ball.yaml"), SCENE);
        List<String> command = new ArrayList<>(Child.java("-Xmx8m"));
        command.addAll(List.of("--config", config.toString(), "--scene", sceneFile.toString()));
        ProcessBuilder builder = new ProcessBuilder(command).directory(dir.toFile())
                .redirectOutput(ProcessBuilder.Redirect.DISCARD);
        builder.environment().put("DISPLAY", ":" + display);
        glint = builder.start();
        glintErr = new BufferedReader(new InputStreamReader(glint.getErrorStream(), StandardCharsets.UTF_8));
        assertEquals(1, finish(), err::toString);
        assertEquals("glint: out of memory; render fewer pixels, samples or threads, or start Java with a larger -Xmx",
                err.get(err.size() - 1), err::toString);
        assertEquals(1, err.stream().filter(l -> l.contains("out of memory")).count(), err::toString);
        assertNoStackTrace();
    }
}
