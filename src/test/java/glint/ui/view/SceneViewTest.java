package glint.ui.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.config.Flags;
import glint.config.Limits;
import glint.input.InputException;
import glint.math.Quaternion;
import glint.math.Vector3d;
import glint.render.LightTransport;
import glint.render.Shading;
import glint.scene.Camera;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import glint.ui.TestScenes;
import glint.ui.frames.ResolutionGovernor;
import glint.ui.input.Action;
import glint.ui.input.CameraController;
import glint.ui.input.InputFrame;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.function.Consumer;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The view owns its camera, settings and window size: every change made through it starts the frame over
 * (compiled again, drawn, refined from the first pass), and a change that changes nothing leaves the
 * refinement where it was. No caller has to know that it must invalidate after writing.
 */
class SceneViewTest {

    private final StatusLine status = new StatusLine(new PrintWriter(new StringWriter(), true));
    private final Config config = Config.defaults().withSamples(8).withRecursionMax(2)
            .withLimits(new Limits(Limits.DEFAULT.maxImagePixels(), Limits.DEFAULT.maxSceneBytes(),
                    Limits.DEFAULT.maxObjects(), Limits.DEFAULT.maxLights(), 3));
    private final FrameSize size = new FrameSize(32, 24, status, new PrintWriter(new StringWriter(), true));
    private SceneView view;

    @BeforeEach
    void open() throws InputException {
        Scene scene = SceneLoader.parse("a.yaml", TestScenes.sphere(0.1, 0.2, 0.3));
        view = new SceneView(new ViewSettings(config, Flags.NONE), new CameraController(scene.camera(), 2, 60),
                size, status);
        view.show(scene, true);
    }

    /** The view after a moving frame and three still passes: refining, nothing to draw. */
    private void refining() {
        view.movingFrameShown();
        view.passesShown(3);
        status.shown();
        assertFalse(view.needFrame());
        assertEquals(3, view.passesDone());
    }

    private void assertStartsOver(String what, Consumer<SceneView> change) {
        refining();
        change.accept(view);
        assertTrue(view.needFrame(), what + ": drawn anew");
        assertEquals(0, view.passesDone(), what + ": refined from the first pass");
        assertTrue(status.isChanged(), what + ": the overlay shows it");
    }

    private void assertLeavesAsItWas(String what, Consumer<SceneView> change) {
        refining();
        change.accept(view);
        assertFalse(view.needFrame(), what);
        assertEquals(3, view.passesDone(), what);
    }

    @Test
    void everySettingChangedThroughTheViewStartsTheFrameOver() {
        assertStartsOver("M", v -> assertEquals("shading phong", v.toggleShading()));
        assertEquals(Shading.PHONG, view.settings().shading());
        assertStartsOver("I", v -> assertEquals("integrator path, shading cook-torrance (path needs it)",
                v.toggleTransport()));
        assertEquals(LightTransport.PATH, view.settings().transport());
        assertEquals(Shading.COOK_TORRANCE, view.settings().shading());
        assertStartsOver("+", v -> assertEquals("depth 3", v.stepDepth(1)));
        assertEquals(3, view.settings().depth());
        assertStartsOver("F5", v -> v.configFile(config.withRecursionMax(1)));
        assertEquals(1, view.settings().depth(), "the config's depth replaces the user's");
        assertEquals(LightTransport.WHITTED, view.settings().transport(), "and its integrator");
    }

    /** Key I chose the path; a new save of the scene asks for phong: the scene's new value wins, Whitted comes back. */
    @Test
    void aReloadNeverLeavesThePathBesidePhong() throws InputException {
        view.toggleTransport();
        view.show(SceneLoader.parse("a.yaml", "render: {shading: phong}\n" + TestScenes.sphere(0.1, 0.2, 0.3)), false);
        assertEquals(Shading.PHONG, view.settings().shading());
        assertEquals(LightTransport.WHITTED, view.settings().transport());
    }

    @Test
    void aNewWindowSizeStartsTheFrameOverWithinTheSettingsBudget() {
        assertLeavesAsItWas("the same size", v -> v.resized(32, 24));
        assertStartsOver("a resize", v -> v.resized(40, 30));
        assertEquals(40, size.width());
        assertEquals(30, size.height());
        assertEquals(new ResolutionGovernor.Size(40, 30), size.fit(1), "1200 pixels: within budget");
        assertEquals("", size.sizeLimit());
        Limits small = new Limits(300, Limits.DEFAULT.maxSceneBytes(), Limits.DEFAULT.maxObjects(),
                Limits.DEFAULT.maxLights(), 3);
        assertStartsOver("F5 with max_image_pixels 300", v -> v.configFile(config.withLimits(small)));
        assertEquals(new ResolutionGovernor.Size(20, 15), size.fit(1), "40x30 halved: 300 pixels");
        assertTrue(size.sizeLimit().contains("max_image_pixels"), size.sizeLimit());
        assertStartsOver("a resize within the new budget", v -> v.resized(20, 15));
        assertEquals("", size.sizeLimit());
    }

    @Test
    void aDepthAtItsBoundChangesNothing() {
        assertEquals("depth 1", view.stepDepth(-1));
        assertLeavesAsItWas("- at 1", v -> assertEquals("depth stays 1 (from 1 to 3, max_recursion)",
                v.stepDepth(-1)));
        assertEquals(1, view.settings().depth());
        view.stepDepth(1);
        view.stepDepth(1);
        assertLeavesAsItWas("+ at 3", v -> assertEquals("depth stays 3 (from 1 to 3, max_recursion)",
                v.stepDepth(1)));
    }

    @Test
    void everyCameraMoveThroughTheViewStartsTheFrameOver() {
        Camera elsewhere = Camera.lookAt(new Vector3d(5, 2, 5), new Vector3d(0, 1, 0), Vector3d.UNIT_Y, 40);
        assertStartsOver("a view's key", v -> v.goTo(elsewhere));
        assertEquals(elsewhere, view.camera());
        assertStartsOver("Home", SceneView::home);
        assertEquals(view.scene().camera(), view.camera());
        assertStartsOver("W held", v -> assertTrue(v.fly(new InputFrame.Builder().hold(Action.FORWARD, 0.5).build())));
        Vector3d flown = view.camera().position().sub(view.scene().camera().position());
        assertEquals(0, flown.sub(new Vector3d(0, 0, 1)).length(), 1e-12,
                "half a second at 2 units a second: " + flown);
        Camera rolled = new Camera(Vector3d.ZERO, Quaternion.fromAxisAngle(Vector3d.UNIT_Z, 0.3), 60);
        view.goTo(rolled);
        assertStartsOver("L", SceneView::level);
        assertNotEquals(rolled, view.camera());
    }

    @Test
    void aMoveThatMovesNothingLeavesTheRefinement() {
        assertLeavesAsItWas("no keys", v -> assertFalse(v.fly(InputFrame.none())));
        assertLeavesAsItWas("L on a level camera", SceneView::level);
    }
}
