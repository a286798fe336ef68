package glint.ui.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.config.Flags;
import glint.config.Limits;
import glint.input.InputException;
import glint.math.Vector3d;
import glint.render.Shading;
import glint.scene.Camera;
import glint.scene.Scene;
import glint.ui.TestScenes;
import glint.ui.capture.Captures;
import glint.ui.capture.Screenshots;
import glint.ui.capture.StillRender;
import glint.ui.input.Action;
import glint.ui.input.CameraController;
import glint.ui.input.InputFrame;
import glint.ui.scenes.Reloads;
import glint.ui.scenes.SceneBrowser;
import glint.ui.scenes.SceneSource;
import glint.ui.view.FrameSize;
import glint.ui.view.SceneView;
import glint.ui.view.StatusLine;
import glint.ui.view.ViewSettings;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What each command key does to the view, the overlay's message and the files, without an engine loop. */
class CommandsTest {

    private static final String VIEWS = """
            views:
              - {name: from above, position: [0, 9, -3], look_at: [0, 0, 0], fov: 50, aperture: 0.2, focus: 7}
              - {position: [2, 1, -2], look_at: [0, 1, 0]}
            """;

    @TempDir
    Path dir;

    private final StringWriter errText = new StringWriter();
    private final PrintWriter err = new PrintWriter(errText, true);
    private final StatusLine status = new StatusLine(err);
    private final AtomicInteger quits = new AtomicInteger();
    private final StringWriter printed = new StringWriter();
    private Path file;
    private SceneSource source;
    private SceneView view;
    private Reloads reloads;
    private Captures captures;
    private Commands commands;

    @BeforeEach
    void open() throws IOException, InputException {
        // depth 3 of at most 3
        Config config = Config.defaults().withSize(32, 24).withSamples(1).withRecursionMax(3)
                .withLimits(new Limits(Limits.DEFAULT.maxImagePixels(), Limits.DEFAULT.maxSceneBytes(),
                        Limits.DEFAULT.maxObjects(), Limits.DEFAULT.maxLights(), 3));
        file = dir.resolve("a.yaml");
        Files.writeString(file, TestScenes.sphere(0.1, 0.2, 0.3) + VIEWS);
        source = new SceneSource(file, () -> config);
        Scene scene = source.loadScene();
        FrameSize size = new FrameSize(32, 24, status, err);
        view = new SceneView(new ViewSettings(config, Flags.NONE), new CameraController(scene.camera(), 2, 60),
                size, status);
        view.show(scene, true);
        reloads = new Reloads(source, view, status, c -> { }, () -> { });
        captures = new Captures(new Screenshots(dir), new StillRender(() -> { }), view, size, source, () -> null, err);
        commands = new Commands(view, status, captures, new SceneBrowser(source, reloads, view, status), reloads,
                quits::incrementAndGet);
        commands.printTo(new PrintWriter(printed, true));
    }

    @AfterEach
    void close() {
        captures.close();
    }

    private void run(Action action) {
        commands.run(action, InputFrame.none());
    }

    private void goTo(int index) {
        InputFrame in = new InputFrame.Builder().view(index).build();
        commands.run(Action.VIEW, in);
    }

    /** The user flew somewhere else than the file's camera. */
    private void flyAway() {
        view.goTo(Camera.lookAt(new Vector3d(5, 2, 5), new Vector3d(0, 1, 0), new Vector3d(0, 1, 0), 40));
    }

    @Test
    void shadingSwitchesAndTheViewIsDrawnAnew() {
        view.movingFrameShown();
        run(Action.TOGGLE_SHADING);
        assertEquals(Shading.PHONG, view.settings().shading());
        assertEquals("shading phong", status.message());
        assertTrue(view.needFrame());
        run(Action.TOGGLE_SHADING);
        assertEquals(Shading.COOK_TORRANCE, view.settings().shading());
    }

    @Test
    void depthStaysWithinOneAndMaxRecursion() {
        view.movingFrameShown();
        run(Action.DEPTH_UP);
        assertEquals(3, view.settings().depth());
        assertEquals("depth stays 3 (from 1 to 3, max_recursion)", status.message());
        assertFalse(view.needFrame(), "nothing to draw again");
        run(Action.DEPTH_DOWN);
        run(Action.DEPTH_DOWN);
        assertEquals("depth 1", status.message());
        assertTrue(view.needFrame());
        run(Action.DEPTH_DOWN);
        assertEquals(1, view.settings().depth());
        assertEquals("depth stays 1 (from 1 to 3, max_recursion)", status.message());
    }

    @Test
    void theLensKeysStepTheApertureAndEachViewBringsItsOwnLens() {
        assertEquals(0, view.camera().aperture(), "the file's camera: a pinhole focused 4 ahead, on its look_at");
        view.movingFrameShown();
        run(Action.APERTURE_WIDER);
        assertEquals(4.0 / 64, view.camera().aperture(), 1e-15);
        assertEquals("aperture 0.0625  focus 4", status.message());
        assertTrue(view.needFrame());
        run(Action.APERTURE_WIDER);
        assertEquals(4.0 / 64 * Math.sqrt(2), view.camera().aperture(), 1e-15);
        run(Action.APERTURE_NARROWER);
        assertEquals(4.0 / 64, view.camera().aperture(), 1e-15);
        run(Action.APERTURE_NARROWER);
        assertEquals(0, view.camera().aperture());
        assertEquals("aperture 0: a pinhole, all in focus", status.message());
        view.movingFrameShown();
        run(Action.APERTURE_NARROWER);
        assertFalse(view.needFrame(), "a pinhole stays one");
        goTo(0);
        assertEquals(0.2, view.camera().aperture());
        assertEquals(7, view.camera().focus());
        run(Action.APERTURE_WIDER);
        goTo(1);
        assertEquals(0, view.camera().aperture());
        assertEquals(Math.sqrt(8), view.camera().focus(), 1e-12, "focused on its look_at");
        goTo(0);
        assertEquals(0.2, view.camera().aperture(), "the view's own lens, whatever the keys did to the last");
        run(Action.PRINT_CAMERA);
        assertTrue(printed.toString().contains("  aperture: 0.2\n  focus: 7\n"), printed.toString());
    }

    @Test
    void viewsHomeAndLevelPutTheCameraSomewhere() {
        Camera file = view.scene().camera();
        goTo(0);
        assertEquals(view.scene().views().get(0).camera(), view.camera());
        assertEquals("view 1: from above", status.message());
        goTo(1);
        assertEquals(view.scene().views().get(1).camera(), view.camera());
        assertEquals("view 2: view 2", status.message());
        goTo(2);
        assertEquals("the scene has 2 views (keys 1 to 2)", status.message());
        assertEquals(view.scene().views().get(1).camera(), view.camera(), "a key beyond the list stays");
        run(Action.HOME);
        assertEquals(file, view.camera());
        assertEquals("the scene's camera", status.message());
        run(Action.LEVEL);
        assertEquals("level", status.message());
    }

    @Test
    void cPrintsTheCameraAsAPastableBlock() {
        run(Action.PRINT_CAMERA);
        assertTrue(printed.toString().startsWith("camera:\n  position: [0, 1, -4]"), printed.toString());
        assertEquals(status.message(), status.message().strip());
        assertFalse(status.message().isEmpty());
    }

    @Test
    void aScreenshotBeforeTheFirstFrameSaysSo() throws IOException {
        run(Action.SCREENSHOT);
        assertEquals("nothing to save yet", status.message());
        try (var files = Files.list(dir)) {
            assertEquals(1, files.count(), "only the scene");
        }
    }

    @Test
    void pageDownOpensTheNextSceneRoundTheFolderAndDropsTheWatchersChange() throws Exception {
        run(Action.NEXT_SCENE);
        assertEquals("no other scene in " + dir.toAbsolutePath().normalize(), status.message());

        Path b = dir.resolve("b.yaml");
        Files.writeString(b, TestScenes.sphere(0.9, 0.1, 0.1));
        flyAway();
        reloads.loaded(source.loadScene()); // a change in a.yaml the watcher saw: no longer wanted
        run(Action.NEXT_SCENE);
        assertEquals(b, source.scenePath());
        assertEquals("opened " + b + " (2 of 2)", status.message());
        assertEquals(new Vector3d(0.9, 0.1, 0.1), view.scene().background());
        assertEquals(view.scene().camera(), view.camera(), "the new scene's camera");
        Scene shown = view.scene();
        reloads.takePending();
        assertSame(shown, view.scene());

        run(Action.NEXT_SCENE); // round to the first
        assertEquals(file, source.scenePath());
        assertEquals("opened " + file + " (1 of 2)", status.message());
    }

    /** The watcher was loading a new save of a.yaml when Page Down opened b.yaml: that load is dropped. */
    @Test
    void aLoadOfTheOldSceneThatEndsAfterPageDownIsDropped() throws Exception {
        Path b = dir.resolve("b.yaml");
        Files.writeString(b, TestScenes.sphere(0.9, 0.1, 0.1));
        Scene oldSave = source.loadScene(file);
        run(Action.NEXT_SCENE);
        Scene opened = view.scene();
        reloads.loaded(file, oldSave); // the load that was under way ends now
        reloads.takePending();
        assertSame(opened, view.scene());
        reloads.failed(file, new InputException(file.toString(), 1, 1, "broken"));
        reloads.takePending();
        assertEquals("", status.error(), "nor is a failure of the old file shown");
        assertEquals("opened " + b + " (2 of 2)", status.message());
    }

    @Test
    void aNeighbourThatDoesNotLoadSaysWhyAndKeepsTheView() throws Exception {
        Files.writeString(dir.resolve("b.yaml"), "camera: [\n");
        Scene before = view.scene();
        run(Action.PREVIOUS_SCENE);
        assertSame(before, view.scene());
        assertEquals("opened " + dir.resolve("b.yaml") + ": it does not load", status.message());
        assertTrue(status.error().startsWith(dir.resolve("b.yaml").toString()), status.error());
    }

    @Test
    void escQuitsWhenNoStillRenders() {
        run(Action.QUIT);
        assertEquals(1, quits.get());
    }

    @Test
    void theOverlayKeysAreTheDisplaysAndChangeNothingHere() {
        view.movingFrameShown();
        run(Action.TOGGLE_OVERLAY);
        run(Action.TOGGLE_HELP);
        assertFalse(view.needFrame());
        assertEquals("", status.message());
        assertEquals(0, quits.get());
        assertNotEquals(Shading.PHONG, view.settings().shading());
    }
}
