package glint.ui.engine;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.app.Main;
import glint.config.Config;
import glint.image.PfmReader;
import glint.input.InputException;
import glint.ui.FakeClock;
import glint.ui.Poll;
import glint.ui.RecordingPresenter;
import glint.ui.TestScenes;
import glint.ui.capture.Screenshots;
import glint.ui.input.Action;
import glint.ui.input.InputState;
import glint.ui.scenes.SceneSource;
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
    private SceneSource source; // the engine's

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
        open(Config.defaults().withSize(W, H).withSamples(samples).withThreads(2), folder);
    }

    private void open(Config config) throws InputException {
        open(config, shots);
    }

    private void open(Config config, Path folder) throws InputException {
        if (engine != null) {
            engine.close();
        }
        source = new SceneSource(sceneFile, () -> config);
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
        stepUntilMatches(java.util.regex.Pattern.quote(prefix) + ".*");
    }

    /** Steps the engine until the overlay's message matches {@code regex}. */
    private void stepUntilMatches(String regex) throws InterruptedException {
        Poll.until(() -> {
            engine.step();
            clock.advance(0.01);
            return message().matches(regex);
        }, 60_000, () -> "the overlay says " + regex + ": " + message() + "; err: " + err);
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
        input.command(Action.EXPOSURE_UP); // half a stop brighter, in the standard curve
        input.command(Action.TOGGLE_TONE);
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
        assertTrue(args.contains("--exposure +0.5 --tone standard"), args);
        StringWriter mainErr = new StringWriter();
        assertEquals(0, Main.run(args.split(" "), new PrintWriter(new StringWriter(), true),
                new PrintWriter(mainErr, true)), mainErr::toString);
        assertArrayEquals(Files.readAllBytes(headless), Files.readAllBytes(png), "the window's still and the headless one");
        Path pfm = png.resolveSibling(png.getFileName().toString().replace(".png", ".pfm"));
        assertEquals(W, PfmReader.read(pfm).width());
    }

    /**
     * The window runs on a config file whose integrator is path, and key I brought Whitted's: the command names
     * the config file and the integrator on screen, and writes the same bytes.
     */
    @Test
    void theCommandNamesTheConfigFileAndTheIntegratorKeyIChose() throws Exception {
        Path configFile = Files.writeString(dir.resolve("path.properties"),
                "integrator=path\ndisplay_width=" + W + "\ndisplay_height=" + H + "\nsamples=4\nthreads=2\n");
        Config config = glint.config.ConfigLoader.load(configFile);
        engine.close();
        SceneSource source = new SceneSource(sceneFile, () -> config, glint.config.Flags.NONE, configFile);
        engine = new Engine(config, source.loadScene(), source, input, presenter, new Screenshots(shots), clock,
                new PrintWriter(err, true));
        engine.printTo(new PrintWriter(out, true));
        input.command(Action.TOGGLE_INTEGRATOR);
        engine.step();
        input.command(Action.RENDER_STILL);
        stepUntil("still: wrote ");
        Path png = files().get(0);
        String printed = out.toString();
        Matcher command = Pattern.compile("java -jar target/glint.jar (.*) --output \\S+\n").matcher(printed);
        assertTrue(command.find(), printed);
        assertTrue(command.group(1).startsWith("--config " + configFile + " --scene "), command.group(1));
        assertTrue(command.group(1).contains(" --integrator bdpt "), command.group(1)); // I: path, then bdpt
        String block = printed.substring(printed.indexOf("camera:\n"));
        String scene = Files.readString(sceneFile);
        Path pasted = Files.writeString(dir.resolve("pasted.yaml"), block + scene.substring(scene.indexOf('\n') + 1));
        Path headless = dir.resolve("headless.png");
        String args = command.group(1).replace("--scene " + sceneFile, "--scene " + pasted) + " --output " + headless;
        StringWriter mainErr = new StringWriter();
        assertEquals(0, Main.run(args.split(" "), new PrintWriter(new StringWriter(), true),
                new PrintWriter(mainErr, true)), mainErr::toString);
        assertArrayEquals(Files.readAllBytes(headless), Files.readAllBytes(png), "the window's still and the headless one");
    }

    /**
     * A scene whose name is 245 characters long (250 with .yaml, which the file system takes): its stills' names
     * keep the first part of it and a code of the whole, within the file system's 255 bytes, and two such scenes
     * that differ only at the end still name their stills apart.
     */
    @Test
    void aStillOfASceneWithALongNameHasAShortenedNameOfItsOwn() throws Exception {
        List<String> stems = new java.util.ArrayList<>();
        for (String end : new String[] {"-one", "-two"}) {
            sceneFile = Files.writeString(dir.resolve("a".repeat(241) + end + ".yaml"), TestScenes.sphere(0.1, 0.2, 0.3));
            open(4);
            List<Path> before = files();
            input.command(Action.RENDER_STILL);
            stepUntilMatches("still: (wrote|not written) .*");
            assertTrue(message().startsWith("still: wrote "), message());
            Path png = files().stream().filter(p -> !before.contains(p)).findFirst().orElseThrow();
            String file = png.getFileName().toString();
            assertTrue(file.matches("a{91}-[0-9a-f]{8}-\\d{8}-\\d{6}-\\d{3}\\.png"), file);
            assertTrue(out.toString().contains(" --output " + file + "\n"), out::toString);
            stems.add(file.substring(0, 100));
            out.getBuffer().setLength(0);
        }
        assertFalse(stems.get(0).equals(stems.get(1)), stems::toString);
        assertEquals("", err.toString());
    }

    /**
     * A scene file whose name holds a line break and a terminal's escape: the still's name has neither, and the
     * report prints the scene's name escaped, its command in bash's quotes, every line as it reads.
     */
    @Test
    void aSceneNameWithALineBreakAndAnEscapeIsPrintedEscaped() throws Exception {
        sceneFile = Files.writeString(dir.resolve("ball\nnew\u001b[2J.yaml"), TestScenes.sphere(0.1, 0.2, 0.3));
        open(4);
        input.command(Action.RENDER_STILL);
        stepUntilMatches("still: (wrote|not written) .*");
        String file = files().get(0).getFileName().toString();
        assertTrue(file.matches("ball_new_\\[2J-\\d{8}-\\d{6}-\\d{3}\\.png"), file);
        String printed = out.toString();
        assertTrue(printed.contains("\nstill: the same image headless, with this camera in " + dir
                + "/ball\\nnew\\u001b[2J.yaml:\n"), printed);
        assertTrue(printed.contains(" --scene $'" + dir + "/ball\\nnew\\u001b[2J.yaml' "), printed);
        assertTrue(printed.contains(" --output \"" + file + "\"\n"), printed);
        assertFalse(printed.contains("\u001b"), printed);
        assertEquals(8, printed.lines().count(), printed); // wrote, the same image, the command, the camera block
    }

    /**
     * The scene file saved again, a version that loads but is not on screen yet (the watcher takes it after two
     * reads): the command would render the new file, so the still is refused and why; once shown, it is rendered.
     */
    @Test
    void aStillIsRefusedWhileASavedVersionThatLoadsIsNotShownYet() throws Exception {
        Files.writeString(sceneFile, TestScenes.sphere(0.6, 0.2, 0.3));
        input.command(Action.RENDER_STILL);
        engine.step();
        assertEquals("still not rendered: the headless command would not give this view: '" + sceneFile
                + "' changed on disk since it was shown; the new version is shown within a second (or its error), then"
                + " Enter renders it", message());
        assertEquals(List.of(), files());
        engine.loaded(sceneFile, source.loadScene()); // what the watcher does: shown at the engine's next turn
        engine.step();
        input.command(Action.RENDER_STILL);
        stepUntilMatches("still: (wrote|not written) .*");
        assertTrue(message().startsWith("still: wrote "), message());
    }

    /** After Page Down onto a scene that does not load, the view is the old scene's: no still, and why. */
    @Test
    void aStillIsRefusedWhileTheSceneFileDoesNotLoadAsShown() throws Exception {
        Files.writeString(dir.resolve("broken.yaml"), "camera: [\n");
        input.command(Action.NEXT_SCENE);
        engine.step();
        input.command(Action.RENDER_STILL);
        engine.step();
        assertTrue(message().startsWith("still not rendered: the headless command would not give this view: "
                + dir.resolve("broken.yaml") + ":"), message());
        assertEquals(List.of(), files());
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

    /** How many still threads are alive: a cancelled still's tile may still be traced, and its result dropped. */
    private static long stillThreads() {
        return Thread.getAllStackTraces().keySet().stream()
                .filter(t -> t.getName().equals("glint-still") && t.isAlive()).count();
    }

    /**
     * Four tiles (screen_divider=2) of a second or so each: once one is done, Enter cancels the still at once,
     * though the tiles under way go on being traced, and the next Enter starts a new still, which is written.
     */
    @Test
    void aCancelledStillIsCancelledAtOnceAndTheNextEnterStartsANewOne() throws Exception {
        Files.writeString(sceneFile, TestScenes.sphere(0.1, 0.2, 0.3) + "render: {width: 480, height: 360}\n");
        open(Config.defaults().withSize(W, H).withSamples(64).withThreads(2).withScreenDivider(2));
        input.command(Action.RENDER_STILL);
        stepUntilMatches("still: rendering [1-9][0-9]? % .*"); // a tile is done: the next ones are being traced
        input.command(Action.RENDER_STILL);
        engine.step(); // one turn: no waiting for the tile
        assertEquals("still: cancelled, nothing written", message(), "cancelled at once");
        assertEquals(1, stillThreads(), "its one tile is still being traced");
        input.command(Action.RENDER_STILL);
        engine.step();
        assertEquals("still: rendering 0 % (Enter or Esc cancels)", message(), "a new still, not a second cancel");
        stepUntil("still: wrote ");
        List<Path> written = files();
        assertEquals(1, written.size(), written::toString);
        assertTrue(message().endsWith(written.get(0).toString()), message());
        assertEquals(1, out.toString().split("still: wrote ", -1).length - 1, out::toString);
    }

    /**
     * A still cancelled while the one before it is still tracing its last tile (it waits for that one to let go
     * of its frame before it opens its files) opens none: nothing is made, then or after, and the next still is
     * written.
     */
    @Test
    void aStillCancelledBeforeItOpensItsFilesMakesNone() throws Exception {
        Files.writeString(sceneFile, TestScenes.sphere(0.1, 0.2, 0.3) + "render: {width: 480, height: 360}\n");
        open(Config.defaults().withSize(W, H).withSamples(64).withThreads(2).withScreenDivider(2));
        input.command(Action.RENDER_STILL);
        stepUntilMatches("still: rendering [1-9][0-9]? % .*"); // a tile is done: the next ones are being traced
        input.command(Action.RENDER_STILL);
        engine.step();
        assertEquals("still: cancelled, nothing written", message());
        input.command(Action.RENDER_STILL); // a new still, waiting for the cancelled one's tile
        engine.step();
        assertEquals("still: rendering 0 % (Enter or Esc cancels)", message());
        input.command(Action.RENDER_STILL);
        engine.step();
        assertEquals("still: cancelled, nothing written", message());
        assertEquals(List.of(), files(), "no hidden file");
        Poll.until(() -> stillThreads() == 0, 60_000, () -> "the stills' threads end: " + stillThreads());
        assertEquals(List.of(), files(), "none made after the cancel either");
        assertEquals("", err.toString());
        input.command(Action.RENDER_STILL);
        stepUntil("still: wrote ");
        List<Path> written = files();
        assertEquals(1, written.size(), written::toString);
    }

    /** Standard output that does not take the still's report (a full disk): the image is there, and that is said. */
    @Test
    void aStillWhoseReportCannotBePrintedSaysSo() throws Exception {
        java.io.File full = new java.io.File("/dev/full");
        org.junit.jupiter.api.Assumptions.assumeTrue(full.exists(), "/dev/full exists here");
        engine.printTo(new PrintWriter(new java.io.FileOutputStream(full), true));
        input.command(Action.RENDER_STILL);
        stepUntil("still: wrote ");
        Path png = files().get(0);
        assertEquals("still: wrote " + png + "; its report not printed: cannot write to standard output", message());
        assertEquals("glint: still: wrote " + png + "; its report not printed: cannot write to standard output\n",
                err.toString());
    }

    /** Esc pressed while the overlay said a still was under way, which ended before the key came: no quitting. */
    @Test
    void aKeyMeantToCancelAStillThatHasJustEndedNeitherQuitsNorStartsOne() throws Exception {
        input.command(Action.RENDER_STILL);
        stepUntil("still: wrote ");
        String wrote = message();
        input.command(Action.CANCEL_STILL); // the listener's Esc or Enter while the overlay said "rendering"
        engine.step();
        assertTrue(engine.isRunning(), "the window stays");
        assertEquals(wrote, message(), "what happened stays on the overlay");
        assertEquals(1, files().size(), "no second still");
    }

    /** A still of 3840x2160 (the scene's render: block): Esc while its PNG is encoded stops the write, and it leaves nothing. */
    @Test
    void escWhileTheImageIsWrittenStopsTheWriteAndLeavesNothing() throws Exception {
        Files.writeString(sceneFile, TestScenes.sphere(0.1, 0.2, 0.3) + "render: {width: 3840, height: 2160}\n");
        open(1);
        input.command(Action.RENDER_STILL);
        stepUntil("still: writing ");
        input.command(Action.QUIT);
        engine.step();
        assertEquals("still: cancelled, nothing written", message());
        assertTrue(engine.isRunning(), "Esc stopped the still, not the window");
        assertEquals(List.of(), files(), "no image and no hidden file, at once");
        engine.close(); // waits until the still's thread has ended
        assertEquals(List.of(), files());
        assertFalse(out.toString().contains("wrote"), out::toString);
        assertEquals("", err.toString());
    }

    @Test
    void closingTheWindowWhileTheImageIsWrittenLeavesNothingAndSaysSo() throws Exception {
        Files.writeString(sceneFile, TestScenes.sphere(0.1, 0.2, 0.3) + "render: {width: 3840, height: 2160}\n");
        open(1);
        input.command(Action.RENDER_STILL);
        stepUntil("still: writing ");
        Thread loop = new Thread(engine, "glint-engine");
        loop.start(); // the loop's end is the window's
        engine.stop();
        assertTrue(engine.awaitFinished(30, java.util.concurrent.TimeUnit.SECONDS));
        assertEquals(List.of(), files(), "no image and no hidden file");
        assertEquals("glint: still cancelled, nothing written (the window closed)\n", err.toString());
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
        assertTrue(message().matches("still not written: cannot write '" + image + "': Not a directory"), message());
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
            assertTrue(message().matches("still not written: cannot write '" + image + "': Permission denied"), message());
            try (var list = Files.list(readOnly)) {
                assertEquals(List.of(), list.toList());
            }
        } finally {
            Files.setPosixFilePermissions(readOnly, java.nio.file.attribute.PosixFilePermissions.fromString("rwxr-xr-x"));
        }
    }

    /**
     * The window and {@code --output} check an image file in one place: the window's still into a folder that
     * is a file is refused in the words the command line refuses the same file with, after its own prefix.
     */
    @Test
    void theWindowAndTheCommandLineRefuseTheSameImageFileInTheSameWords() throws Exception {
        Path notAFolder = Files.writeString(dir.resolve("not-a-folder"), "");
        open(1, notAFolder);
        input.command(Action.RENDER_STILL);
        stepUntil("still not written: ");
        String problem = message().substring("still not written: ".length());
        Matcher image = Pattern.compile("cannot write '(.*)': .*").matcher(problem);
        assertTrue(image.matches(), problem);
        Path config = Files.writeString(dir.resolve("empty.properties"), "");
        StringWriter mainErr = new StringWriter();
        assertEquals(Main.BAD_INPUT, Main.run(new String[] {"--config", config.toString(), "--scene", sceneFile.toString(),
                "--output", image.group(1)}, new PrintWriter(new StringWriter(), true), new PrintWriter(mainErr, true)));
        assertEquals("glint: --output: " + problem + "\n", mainErr.toString());
    }
}
