package glint.ui.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;

import glint.config.Config;
import glint.input.InputException;
import glint.ui.FakeClock;
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
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Z and X show the field of view in the overlay while they change it (the engine on a fake clock). */
class FovNoteTest {

    @TempDir
    Path dir;

    private final FakeClock clock = new FakeClock();
    private final InputState input = new InputState(clock, 32, 24);
    private final RecordingPresenter presenter = new RecordingPresenter();
    private Engine engine;

    @BeforeEach
    void start() throws IOException, InputException {
        Path scene = Files.writeString(dir.resolve("scene.yaml"), TestScenes.sphere(0.1, 0.2, 0.3)); // fov 60
        Config config = Config.defaults().withSize(32, 24).withSamples(1).withThreads(1);
        SceneSource source = new SceneSource(scene, () -> config);
        engine = new Engine(config, source.loadScene(), source, input, presenter, new Screenshots(dir), clock,
                new PrintWriter(new StringWriter(), true));
        engine.step();
    }

    @AfterEach
    void stop() {
        engine.close();
    }

    private String hold(Action key, double seconds) {
        input.press(key);
        clock.advance(seconds);
        engine.step();
        return presenter.last().stats().message();
    }

    @Test
    void holdingZShowsTheNarrowingFieldOfViewEachFrame() {
        assertEquals(60, engine.camera().fovDegrees());
        assertEquals("fov 42.4 degrees", hold(Action.ZOOM_IN, 0.5)); // 60 / 2^0.5
        assertEquals("fov 30.0 degrees", hold(Action.ZOOM_IN, 0.5));
        input.release(Action.ZOOM_IN);
        assertEquals("fov 30.0 degrees", hold(Action.ZOOM_OUT, 0)); // pressed, not yet held: no change, no note
        assertEquals("fov 60.0 degrees", hold(Action.ZOOM_OUT, 1));
    }

    @Test
    void theBoundsAreNamedWhenReached() {
        assertEquals("fov 150.0 degrees (the widest)", hold(Action.ZOOM_OUT, 5));
        input.release(Action.ZOOM_OUT);
        assertEquals("fov 1.0 degrees (the narrowest)", hold(Action.ZOOM_IN, 20));
    }

    @Test
    void otherMotionLeavesTheNoteAlone() {
        assertEquals("", hold(Action.FORWARD, 0.5));
    }
}
