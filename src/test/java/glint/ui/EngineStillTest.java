package glint.ui;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.app.Main;
import glint.config.Config;
import glint.image.PfmReader;
import glint.input.InputException;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The render key: the view as a still, in the background, written whole or not at all, and byte for byte
 * what the printed headless command writes. The engine is driven step by step; the still has its own thread.
 */
class EngineStillTest {

    private static final int W = 48;
    private static final int H = 36;

    @TempDir
    Path dir;

    private final FakeClock clock = new FakeClock();
    private final InputState input = new InputState(clock, W, H);
    private final RecordingPresenter presenter = new RecordingPresenter();
    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();
    private Path sceneFile;
    private Path shots;
    private Engine engine;

    @BeforeEach
    void start() throws IOException, InputException {
        sceneFile = Files.writeString(dir.resolve("ball.yaml"), TestScenes.sphere(0.1, 0.2, 0.3));
        shots = Files.createDirectory(dir.resolve("shots"));
        open(4);
    }

    /** An engine whose stills take {@code samples} samples a pixel. */
    private void open(int samples) throws InputException {
        open(samples, shots);
    }

    /** An engine whose stills take {@code samples} samples a pixel and go to {@code folder}. */
    private void open(int samples, Path folder) throws InputException {
        if (engine != null) {
            engine.close();
        }
        Config config = Config.defaults().withSize(W, H).withSamples(samples).withThreads(2);
        SceneSource source = new SceneSource(sceneFile, () -> config);
        engine = new Engine(config, source.loadScene(), source, input, presenter, new Screenshots(folder), clock,
                new PrintWriter(err, true));
        engine.printTo(new PrintWriter(out, true));
    }

    @AfterEach
    void stop() {
        engine.close();
    }

    private String message() {
        return presenter.last() == null ? "" : presenter.last().stats().message();
    }

    /** Steps the engine (as its loop would) until the overlay's message starts with {@code prefix}. */
    private void stepUntil(String prefix) throws InterruptedException {
        Poll.until(() -> {
            engine.step();
            clock.advance(0.01);
            return message().startsWith(prefix);
        }, 60_000, () -> "the overlay says " + prefix + "...: " + message() + "; err: " + err);
    }

    private List<Path> files() throws IOException {
        try (var list = Files.list(shots)) {
            return list.sorted().toList();
        }
    }

    @Test
    void theStillIsWhatThePrintedHeadlessCommandWritesByteForByte() throws Exception {
        input.drag(37, -11); // somewhere the scene file does not say
        input.command(Action.ZOOM_IN); // not a command: ignored
        engine.step();
        input.command(Action.TOGGLE_SHADING); // what is on screen: phong
        input.command(Action.RENDER_STILL_PFM);
        stepUntil("still: wrote ");
        List<Path> written = files();
        assertEquals(2, written.size(), written::toString);
        Path png = written.stream().filter(p -> p.toString().endsWith(".png")).findFirst().orElseThrow();
        assertTrue(png.getFileName().toString().matches("ball-\\d{8}-\\d{6}-\\d{3}\\.png"), png.toString());
        assertTrue(message().contains(png.toString()), message());
        String printed = out.toString();
        assertTrue(printed.startsWith("still: wrote " + png), printed);

        Matcher command = Pattern.compile("java -jar target/glint.jar (.*) --output \\S+\n").matcher(printed);
        assertTrue(command.find(), printed);
        String block = printed.substring(printed.indexOf("camera:\n"));
        String scene = Files.readString(sceneFile);
        Path pasted = Files.writeString(dir.resolve("pasted.yaml"), block + scene.substring(scene.indexOf('\n') + 1));
        Path config = Files.writeString(dir.resolve("empty.properties"), "");
        Path headless = dir.resolve("headless.png");
        String args = command.group(1).replace("--scene " + sceneFile, "--scene " + pasted)
                + " --config " + config + " --output " + headless;
        assertTrue(args.contains("--shading phong"), args);
        StringWriter mainErr = new StringWriter();
        assertEquals(0, Main.run(args.split(" "), new PrintWriter(new StringWriter(), true),
                new PrintWriter(mainErr, true)), mainErr::toString);
        assertArrayEquals(Files.readAllBytes(headless), Files.readAllBytes(png), "the window's still and the headless one");
        Path pfm = png.resolveSibling(png.getFileName().toString().replace(".png", ".pfm"));
        assertEquals(W, PfmReader.read(pfm).width());
    }

    @Test
    void theSameKeyOrEscCancelsAndNothingIsWritten() throws Exception {
        open(4096); // long enough to be cancelled while it runs, even on a loaded machine
        input.resize(640, 480);
        input.command(Action.RENDER_STILL);
        stepUntil("still: rendering");
        input.command(Action.RENDER_STILL);
        stepUntil("still: cancelled, nothing written");
        assertEquals(List.of(), files());
        input.command(Action.RENDER_STILL);
        stepUntil("still: rendering");
        input.command(Action.QUIT);
        stepUntil("still: cancelled, nothing written");
        assertTrue(engine.isRunning(), "Esc stopped the still, not the window");
        assertEquals(List.of(), files());
        assertFalse(out.toString().contains("wrote"), out::toString);
    }

    @Test
    void closingTheWindowWhileAStillRendersLeavesNoFile() throws Exception {
        open(1024);
        input.resize(640, 480);
        input.command(Action.RENDER_STILL);
        stepUntil("still: rendering");
        engine.close(); // as the loop's end does: cancels the still and waits for its thread
        assertEquals(List.of(), files(), "no image and no hidden part file");
    }

    @Test
    void aStillThatCannotBeWrittenNamesTheImageAndWhyNeverItsTemporaryFile() throws Exception {
        Path notAFolder = Files.writeString(dir.resolve("not-a-folder"), "");
        open(1, notAFolder);
        input.command(Action.RENDER_STILL);
        stepUntil("still not written: ");
        String image = Pattern.quote(notAFolder + "/") + "ball-\\d{8}-\\d{6}-\\d{3}\\.png";
        assertTrue(message().matches("still not written: " + image + ": Not a directory"), message());
        assertTrue(err.toString().contains("glint: " + message() + "\n"), err::toString);
        assertFalse(err.toString().contains(".part"), err::toString);
    }

    @Test
    void aStillInAReadOnlyFolderSaysPermissionDenied() throws Exception {
        org.junit.jupiter.api.Assumptions.assumeFalse("root".equals(System.getProperty("user.name")),
                "root may write in a read-only folder");
        Path readOnly = Files.createDirectory(dir.resolve("read-only"));
        Files.setPosixFilePermissions(readOnly, java.nio.file.attribute.PosixFilePermissions.fromString("r-xr-xr-x"));
        try {
            open(1, readOnly);
            input.command(Action.RENDER_STILL);
            stepUntil("still not written: ");
            String image = Pattern.quote(readOnly + "/") + "ball-\\d{8}-\\d{6}-\\d{3}\\.png";
            assertTrue(message().matches("still not written: " + image + ": permission denied"), message());
            try (var list = Files.list(readOnly)) {
                assertEquals(List.of(), list.toList());
            }
        } finally {
            Files.setPosixFilePermissions(readOnly, java.nio.file.attribute.PosixFilePermissions.fromString("rwxr-xr-x"));
        }
    }

    @Test
    void whyAStillFailedNamesTheImageNotTheFileTheSystemNamed() {
        Path png = Path.of("/photos/ball.png");
        assertEquals("/photos/ball.png: permission denied",
                StillRender.why(new java.nio.file.AccessDeniedException("/photos/.ball.png.3a8.part"), png));
        assertEquals("/photos/ball.png: No space left on device", StillRender.why(
                new java.nio.file.FileSystemException("/photos/.ball.png.3a8.part", null, "No space left on device"), png));
        assertEquals("/photos/ball.png: File too large", StillRender.why(new IOException("File too large"), png));
    }
}
