package glint.ui.scenes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.config.Flags;
import glint.input.InputException;
import glint.math.Vector3d;
import glint.render.Shading;
import glint.scene.Camera;
import glint.scene.Scene;
import glint.ui.TestScenes;
import glint.ui.input.CameraController;
import glint.ui.view.FrameSize;
import glint.ui.view.SceneView;
import glint.ui.view.StatusLine;
import glint.ui.view.ViewSettings;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Reading the files again: the watcher's changes are handed to the engine thread as typed values and taken
 * at its next turn, the latest one only; F5 reads the config and the scene, and says what failed.
 */
class ReloadsTest {

    @TempDir
    Path dir;

    private final StringWriter errText = new StringWriter();
    private final StatusLine status = new StatusLine(new PrintWriter(errText, true));
    private final List<Config> configured = new ArrayList<>();
    private final AtomicInteger wakes = new AtomicInteger();
    private Config config;
    private InputException configProblem;
    private Path file;
    private SceneSource source;
    private SceneView view;
    private Reloads reloads;

    @BeforeEach
    void open() throws IOException, InputException {
        config = Config.defaults().withSize(32, 24).withSamples(1);
        file = dir.resolve("scene.yaml");
        Files.writeString(file, TestScenes.sphere(0.1, 0.2, 0.3));
        source = new SceneSource(file, () -> {
            if (configProblem != null) {
                throw configProblem;
            }
            return config;
        });
        Scene scene = source.loadScene();
        view = new SceneView(new ViewSettings(config, Flags.NONE), new CameraController(scene.camera(), 2, 60),
                new FrameSize(32, 24, status, new PrintWriter(new StringWriter(), true)), status);
        view.show(scene, true);
        reloads = new Reloads(source, view, status, configured::add, wakes::incrementAndGet);
    }

    private Scene load(String text) throws IOException, InputException {
        Files.writeString(file, text);
        return source.loadScene();
    }

    /** The user flew somewhere else than the file's camera. */
    private Camera flyAway() {
        Camera elsewhere = Camera.lookAt(new Vector3d(5, 2, 5), new Vector3d(0, 1, 0), new Vector3d(0, 1, 0), 40);
        view.goTo(elsewhere);
        return view.controller().camera();
    }

    @Test
    void aLoadedVersionIsShownAtTheEnginesNextTurnAndKeepsTheUsersCamera() throws Exception {
        Scene before = view.scene();
        Camera flown = flyAway();
        Scene saved = load(TestScenes.sphere(0.9, 0.1, 0.1)); // the same camera: the user's view stays

        reloads.loaded(saved);
        assertEquals(1, wakes.get(), "the engine is woken");
        assertSame(before, view.scene(), "nothing changes before the engine's turn");

        view.movingFrameShown();
        reloads.takePending();
        assertSame(saved, view.scene());
        assertSame(saved, view.sceneNow());
        assertEquals(flown, view.controller().camera());
        assertEquals("reloaded " + file, status.message());
        assertTrue(view.needFrame(), "the view is drawn anew");

        status.note("something else");
        reloads.takePending(); // taken once
        assertEquals("something else", status.message());
    }

    @Test
    void aVersionWithAnotherCameraTakesItsCamera() throws Exception {
        flyAway();
        Scene moved = load(TestScenes.sphere(0.1, 0.2, 0.3).replace("position: [0, 1, -4]", "position: [0, 2, -6]"));
        reloads.loaded(moved);
        reloads.takePending();
        assertEquals(moved.camera(), view.controller().camera());
        assertEquals(moved.camera(), view.camera());
    }

    @Test
    void aVersionThatDoesNotLoadKeepsTheSceneAndShowsWhyOnce() {
        Scene before = view.scene();
        InputException problem = new InputException(file.toString(), 3, 7, "expected a number");
        reloads.failed(problem);
        reloads.takePending();
        assertSame(before, view.scene());
        assertEquals(problem.getMessage(), status.error());
        reloads.failed(problem); // the same again: not printed again
        reloads.takePending();
        assertEquals(1, errText.toString().split(problem.getMessage(), -1).length - 1, errText.toString());
        assertEquals(2, wakes.get());
    }

    @Test
    void onlyTheLatestChangeIsTaken() throws Exception {
        Scene before = view.scene();
        reloads.loaded(load(TestScenes.sphere(0.9, 0.1, 0.1)));
        InputException problem = new InputException(file.toString(), 1, 1, "broken");
        reloads.failed(problem);
        reloads.takePending();
        assertSame(before, view.scene(), "the loaded version was overtaken by the broken one");
        assertEquals(problem.getMessage(), status.error());
    }

    @Test
    void aDiscardedChangeIsNotShown() throws Exception {
        Scene before = view.scene();
        reloads.loaded(load(TestScenes.sphere(0.9, 0.1, 0.1)));
        reloads.discardPending();
        reloads.takePending();
        assertSame(before, view.scene());
        assertEquals("", status.message());
    }

    @Test
    void f5ReadsTheConfigAndTheSceneAndTakesTheScenesCamera() throws Exception {
        Camera flown = flyAway();
        config = config.withShading(Shading.PHONG);
        Scene saved = load(TestScenes.sphere(0.9, 0.1, 0.1));

        reloads.reload();
        assertEquals(List.of(config), configured);
        assertEquals(new Vector3d(0.9, 0.1, 0.1), view.scene().background());
        assertNotEquals(flown, view.controller().camera());
        assertEquals(saved.camera(), view.controller().camera());
        assertEquals("reloaded " + file, status.message());
        assertEquals("", status.error());
    }

    @Test
    void f5WithABrokenConfigStillReadsTheSceneAndSaysWhy() throws Exception {
        configProblem = new InputException("config.properties", 4, 1, "unknown key");
        load(TestScenes.sphere(0.9, 0.1, 0.1));
        reloads.reload();
        assertTrue(configured.isEmpty());
        assertEquals(new Vector3d(0.9, 0.1, 0.1), view.scene().background());
        assertEquals(configProblem.getMessage(), status.error());
        assertEquals("reload failed", status.message());
    }

    @Test
    void f5WithBothBrokenShowsTheConfigsProblemAndKeepsTheScene() throws Exception {
        Scene before = view.scene();
        configProblem = new InputException("config.properties", 4, 1, "unknown key");
        Files.writeString(file, "camera: [\n");
        reloads.reload();
        assertSame(before, view.scene());
        assertEquals(configProblem.getMessage(), status.error());
        assertEquals("reload failed", status.message());
        assertFalse(errText.toString().isEmpty());
    }
}
