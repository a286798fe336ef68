package glint.ui.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;

import glint.config.Config;
import glint.config.Flags;
import glint.input.InputException;
import glint.render.Shading;
import glint.ui.FakeClock;
import glint.ui.RecordingPresenter;
import glint.ui.TestScenes;
import glint.ui.capture.Screenshots;
import glint.ui.input.Action;
import glint.ui.input.InputState;
import glint.ui.scenes.SceneSource;
import glint.ui.screen.FrameStats;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The window sees each scene with its render: block, under the command line's flags, wherever it comes from. */
class EngineRenderBlockTest {

    @TempDir
    Path dir;

    private final FakeClock clock = new FakeClock();
    private final InputState input = new InputState(clock, 32, 24);
    private final RecordingPresenter presenter = new RecordingPresenter();
    private Engine engine;

    @AfterEach
    void stop() {
        if (engine != null) {
            engine.close();
        }
    }

    private Engine open(Path scene, Flags flags) throws InputException {
        Config config = Config.defaults().withSize(32, 24).withSamples(4).withThreads(1);
        SceneSource source = new SceneSource(scene, () -> config, flags);
        engine = new Engine(config, source.loadScene(), source, input, presenter, new Screenshots(dir), clock,
                new PrintWriter(new StringWriter(), true));
        return engine;
    }

    private FrameStats settle() {
        while (engine.step() != Engine.IDLE) {
            clock.advance(0.01);
        }
        return presenter.last().stats();
    }

    private void scenes() throws IOException {
        Files.writeString(dir.resolve("a-plain.yaml"), TestScenes.sphere(0.1, 0.2, 0.3));
        Files.writeString(dir.resolve("b-phong.yaml"), TestScenes.sphere(0.1, 0.2, 0.3)
                + "render: {shading: phong, samples: 1, recursion_max: 3}\n");
    }

    @Test
    void aSceneOpenedByPageDownIsSeenWithItsBlockAndTheNextOneWithout() throws Exception {
        scenes();
        open(dir.resolve("a-plain.yaml"), Flags.NONE);
        FrameStats plain = settle();
        assertEquals(Shading.COOK_TORRANCE, plain.shading());
        assertEquals(4, plain.samplesTotal());
        input.command(Action.NEXT_SCENE);
        FrameStats phong = settle();
        assertEquals(Shading.PHONG, phong.shading());
        assertEquals(1, phong.samplesTotal());
        assertEquals(3, phong.depth());
        input.command(Action.NEXT_SCENE);
        FrameStats back = settle();
        assertEquals(Shading.COOK_TORRANCE, back.shading());
        assertEquals(16, back.depth());
    }

    @Test
    void aSceneOpenedAtStartIsSeenWithItsBlockAndFlagsBeatIt() throws Exception {
        scenes();
        open(dir.resolve("b-phong.yaml"), new Flags(null, null, 9, null, null, null));
        FrameStats s = settle();
        assertEquals(Shading.PHONG, s.shading());
        assertEquals(9, s.samplesTotal(), "--spp beats the block");
        assertEquals(9, s.samplesDone());
    }

    @Test
    void theUsersShadingHoldsOverAReloadThatLeavesTheBlockAlone() throws Exception {
        scenes();
        Path file = dir.resolve("b-phong.yaml");
        open(file, Flags.NONE);
        settle();
        input.command(Action.TOGGLE_SHADING);
        assertEquals(Shading.COOK_TORRANCE, settle().shading());
        TestScenes.replace(file, Files.readString(file).replace("[0.1, 0.2, 0.3]", "[0.3, 0.2, 0.1]"));
        engine.loaded(new SceneSource(file, null).loadScene());
        assertEquals(Shading.COOK_TORRANCE, settle().shading(), "M holds");
        TestScenes.replace(file, Files.readString(file).replace("recursion_max: 3", "recursion_max: 5"));
        engine.loaded(new SceneSource(file, null).loadScene());
        FrameStats s = settle();
        assertEquals(5, s.depth(), "the block's new depth is taken");
        assertEquals(Shading.COOK_TORRANCE, s.shading(), "its shading did not change: M still holds");
    }
}
