package glint.ui.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.config.Flags;
import glint.image.FrameBuffer;
import glint.image.Srgb;
import glint.image.ViewTransform;
import glint.input.InputException;
import glint.render.LightTransport;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Shading;
import glint.render.Tracer;
import glint.scene.Scene;
import glint.ui.FakeClock;
import glint.ui.RecordingPresenter;
import glint.ui.TestScenes;
import glint.ui.capture.Captures;
import glint.ui.capture.Screenshots;
import glint.ui.capture.StillRender;
import glint.ui.frames.FrameRenderer;
import glint.ui.frames.Refinement;
import glint.ui.frames.ResolutionGovernor;
import glint.ui.input.Action;
import glint.ui.input.CameraController;
import glint.ui.input.InputFrame;
import glint.ui.scenes.Reloads;
import glint.ui.scenes.SceneBrowser;
import glint.ui.scenes.SceneSource;
import glint.ui.screen.FrameStats;
import glint.ui.view.FrameSize;
import glint.ui.view.SceneView;
import glint.ui.view.StatusLine;
import glint.ui.view.ViewSettings;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The window with the path integrator: key I switches it (and phong and the path exclude each other),
 * the view at rest accumulates path samples past the still's count, pattern by pattern, its first
 * pattern is the still of as many samples, and the overlay's noise estimate falls as samples come.
 */
class PathRefinementTest {

    private static final int W = 24, H = 18;

    @TempDir
    Path dir;

    private final FakeClock clock = new FakeClock();
    private final StringWriter errText = new StringWriter();
    private final PrintWriter err = new PrintWriter(errText, true);
    private final StatusLine status = new StatusLine(err);
    private final RecordingPresenter presenter = new RecordingPresenter();
    private Scene scene;
    private Config config;
    private SceneView view;
    private FrameMaker maker;
    private Commands commands;

    @BeforeEach
    void open() throws IOException, InputException {
        config = Config.defaults().withSize(W, H).withSamples(4).withThreads(2)
                .withView(ViewTransform.STANDARD); // pixels compared with the plain sRGB encoding
        Path file = dir.resolve("scene.yaml");
        Files.writeString(file, TestScenes.sphere(0.4, 0.5, 0.8)); // a sky: every matte point sees it
        SceneSource source = new SceneSource(file, () -> config);
        scene = source.loadScene();
        FrameSize size = new FrameSize(W, H, status, err);
        view = new SceneView(new ViewSettings(config, Flags.NONE), new CameraController(scene.camera(), 2, 60),
                size, status);
        view.show(scene, true);
        FrameRenderer renderer = new FrameRenderer(2, 4);
        RenderFaults faults = new RenderFaults();
        FrameOutput frames = new FrameOutput(presenter, view, size, status, source, renderer, faults, err);
        maker = new FrameMaker(renderer, new ResolutionGovernor(30, 1), faults, view, size, frames, status, clock,
                err);
        Captures captures = new Captures(new Screenshots(dir), new StillRender(() -> { }), view, size, source,
                () -> null, err);
        Reloads reloads = new Reloads(source, view, status, c -> { }, () -> { });
        commands = new Commands(view, status, captures, new SceneBrowser(source, reloads, view, status), reloads,
                () -> { });
    }

    @AfterEach
    void close() {
        maker.close();
    }

    private void press(Action action) {
        commands.run(action, InputFrame.none());
    }

    @Test
    void keyISwitchesTheIntegratorAndPhongAndThePathExcludeEachOther() {
        view.movingFrameShown();
        press(Action.TOGGLE_INTEGRATOR);
        assertEquals(LightTransport.PATH, view.settings().transport());
        assertEquals("integrator path", status.message());
        assertTrue(view.needFrame(), "drawn anew");
        assertEquals(LightTransport.PATH, view.settings().render().transport());
        press(Action.TOGGLE_SHADING);
        assertEquals(Shading.PHONG, view.settings().shading());
        assertEquals(LightTransport.WHITTED, view.settings().transport());
        assertEquals("shading phong, integrator whitted (path needs cook-torrance)", status.message());
        press(Action.TOGGLE_INTEGRATOR);
        assertEquals(Shading.COOK_TORRANCE, view.settings().shading());
        assertEquals(LightTransport.PATH, view.settings().transport());
        assertEquals("integrator path, shading cook-torrance (path needs it)", status.message());
        press(Action.TOGGLE_INTEGRATOR);
        assertEquals(LightTransport.BDPT, view.settings().transport());
        assertEquals("integrator bdpt", status.message());
        press(Action.TOGGLE_SHADING);
        assertEquals("shading phong, integrator whitted (bdpt needs cook-torrance)", status.message());
        press(Action.TOGGLE_SHADING);
        press(Action.TOGGLE_INTEGRATOR);
        press(Action.TOGGLE_INTEGRATOR);
        press(Action.TOGGLE_INTEGRATOR);
        assertEquals(LightTransport.WHITTED, view.settings().transport());
        assertEquals("integrator whitted", status.message());
    }

    @Test
    void atRestThePathRefinesPastTheStillsSamplesAndItsFirstPatternIsTheStill() {
        press(Action.TOGGLE_INTEGRATOR);
        assertTrue(maker.moving(clock.nanoTime()));
        double noiseAtSixteen = Double.NaN; // two rounds of 8: the first estimate
        while (view.passesDone() < Refinement.PATH_PATTERN) {
            clock.advance(0.01);
            int before = view.passesDone();
            assertTrue(maker.pass(clock.nanoTime()));
            assertTrue(view.passesDone() <= Refinement.PATH_PATTERN, "a call never crosses a pattern's end");
            FrameStats stats = presenter.last().stats();
            assertFalse(stats.refined(), "no end at " + stats.samplesDone());
            if (before < 16 && view.passesDone() >= 16) {
                noiseAtSixteen = stats.noise();
            }
        }
        FrameStats sixtyFour = presenter.last().stats();
        assertEquals(64, sixtyFour.samplesDone());
        assertTrue(sixtyFour.noise() > 0 && sixtyFour.noise() < 0.7 * noiseAtSixteen,
                "the noise falls as samples come: " + noiseAtSixteen + " at 16, " + sixtyFour.noise() + " at 64");
        assertSameAsTheStill(presenter.last().image(), 64);
        while (view.passesDone() < 70) { // past the still's 4 samples and the first pattern
            clock.advance(0.01);
            assertTrue(maker.pass(clock.nanoTime()));
        }
        assertEquals(LightTransport.PATH, presenter.last().stats().transport());
        assertTrue(presenter.last().stats().samplesDone() >= 70);
    }

    /** The window's image is the still of {@code samples} path samples, to an 8-bit level. */
    private void assertSameAsTheStill(BufferedImage shown, int samples) {
        RenderSettings path = config.withTransport(LightTransport.PATH).renderSettings();
        FrameBuffer still = new FrameBuffer(W, H);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(RenderScene.compile(scene, path).withCamera(view.camera()), still, samples, 0, 3);
        }
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int rgb = shown.getRGB(x, y), expected = Srgb.to8Bit(still.rgb()[3 * (y * W + x)]);
                assertEquals(expected, rgb >> 16 & 0xFF, 1.0, "red at " + x + ", " + y);
            }
        }
    }
}
