package glint.scenefile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.scene.Camera;
import glint.scene.Scene;
import glint.scene.View;
import org.junit.jupiter.api.Test;

/** The scene key {@code views:}: cameras the window's keys 1 to 9 go to, and what is wrong with bad ones. */
class SceneViewsTest {

    private static final String FILE = "scenes/v.yaml";

    private static String error(String text) {
        return assertThrows(InputException.class, () -> SceneLoader.parse(FILE, text)).getMessage();
    }

    @Test
    void viewsAreCamerasWithNames() throws InputException {
        Scene s = SceneLoader.parse(FILE, """
                views:
                  - {name: overhead, position: [0, 10, 0], look_at: [0, 0, 0], up: [0, 0, 1], fov: 30}
                  - position: [1, 2, 3]
                    look_at: [1, 2, 4]
                """);
        assertEquals(2, s.views().size());
        assertEquals(new View("overhead", Camera.lookAt(new Vector3d(0, 10, 0), Vector3d.ZERO, Vector3d.UNIT_Z, 30)),
                s.views().get(0));
        assertEquals(new View("view 2", Camera.lookAt(new Vector3d(1, 2, 3), new Vector3d(1, 2, 4), Vector3d.UNIT_Y,
                Camera.DEFAULT_FOV)), s.views().get(1));
        assertEquals(Camera.defaults(), s.camera()); // views leave the scene's camera alone
    }

    @Test
    void aCameraAndEachViewHaveTheirOwnLens() throws InputException {
        Scene s = SceneLoader.parse(FILE, """
                camera: {position: [0, 1, -5], look_at: [0, 1, 0], aperture: 0.1, focus: 4.5}
                views:
                  - {name: near, position: [0, 1, -2], look_at: [0, 1, 1], aperture: 0.25}
                  - {name: far, position: [0, 1, -9], focus: 12}
                  - {name: pinhole, position: [0, 1, -9], look_at: [0, 1, -6]}
                """);
        assertEquals(0.1, s.camera().aperture());
        assertEquals(4.5, s.camera().focus());
        // focus defaults to the distance from position to look_at, or one unit without a look_at
        assertEquals(0.25, s.views().get(0).camera().aperture());
        assertEquals(3, s.views().get(0).camera().focus());
        assertEquals(0, s.views().get(1).camera().aperture());
        assertEquals(12, s.views().get(1).camera().focus());
        assertEquals(0, s.views().get(2).camera().aperture());
        assertEquals(3, s.views().get(2).camera().focus());
        assertEquals(1, SceneLoader.parse(FILE, "camera: {position: [0, 1, -5]}\n").camera().focus());
        assertEquals(Camera.DEFAULT_FOCUS, Camera.defaults().focus());
    }

    @Test
    void noViewsOrAnEmptyKeyIsNoViews() throws InputException {
        assertTrue(SceneLoader.parse(FILE, "ambient: [0, 0, 0]\n").views().isEmpty());
        assertTrue(SceneLoader.parse(FILE, "views:\n").views().isEmpty());
        assertTrue(SceneLoader.parse(FILE, "views: []\n").views().isEmpty());
    }

    @Test
    void nineViewsAtMost() throws InputException {
        String nine = "views:\n" + "  - {position: [0, 1, -5]}\n".repeat(9);
        assertEquals(9, SceneLoader.parse(FILE, nine).views().size());
        assertEquals("scenes/v.yaml:11:5: too many views: at most 9 (keys 1 to 9 go to them)",
                error(nine + "  - {position: [0, 1, -5]}\n"));
    }

    @Test
    void viewsMustBeAListOfMappings() {
        assertEquals("scenes/v.yaml:1:8: expected a list of views, got a mapping",
                error("views: {position: [0, 1, -5]}\n"));
        assertEquals("scenes/v.yaml:2:5: expected a mapping for view 1, got 'overhead'",
                error("views:\n  - overhead\n"));
    }

    @Test
    void unknownKeyInAViewIsNamedWithASuggestion() {
        assertEquals("scenes/v.yaml:3:27: unknown key 'lookat' in view 2 (did you mean 'look_at'?)", error("""
                views:
                  - {name: a}
                  - {position: [0, 0, 0], lookat: [0, 0, 1]}
                """));
    }

    @Test
    void namesAreTextAndDifferent() {
        assertEquals("scenes/v.yaml:3:12: duplicate view name 'a', already the name of view 1; each view needs a name of its own", error("""
                views:
                  - {name: a}
                  - {name: a, fov: 40}
                """));
        assertEquals("scenes/v.yaml:2:12: expected a name for view 1, got a list", error("""
                views:
                  - {name: [a]}
                """));
    }

    @Test
    void aDefaultNameCountsAsTaken() {
        assertEquals("scenes/v.yaml:3:5: view 2 has no name, and its default name 'view 2' is already the name of view 1; "
                + "give view 2 a name of its own", error("""
                views:
                  - {name: view 2}
                  - {}
                """));
        assertEquals("scenes/v.yaml:3:12: duplicate view name 'view 1', already the default name of view 1; "
                + "each view needs a name of its own", error("""
                views:
                  - {fov: 40}
                  - {name: view 1}
                """));
    }

    @Test
    void aNameIsNotEmpty() {
        assertEquals("scenes/v.yaml:3:12: the name of view 2 is empty; expected a name such as 'front', or no name for 'view 2'",
                error("""
                views:
                  - {name: a}
                  - {name: ""}
                """));
        assertEquals("scenes/v.yaml:2:12: the name of view 1 is empty; expected a name such as 'front', or no name for 'view 1'",
                error("""
                views:
                  - {name: "   "}
                """));
    }

    @Test
    void aLongDuplicateNameIsCutInTheMessage() {
        String name = "n".repeat(5000);
        assertEquals("scenes/v.yaml:3:12: duplicate view name '" + "n".repeat(60) + "...', already the name of view 1; "
                + "each view needs a name of its own", error("views:\n  - {name: " + name + "}\n  - {name: " + name + "}\n"));
    }

    @Test
    void aViewIsCheckedLikeTheCamera() {
        assertEquals("scenes/v.yaml:2:11: fov must lie strictly between 0 and 180 degrees, got 180", error("""
                views:
                  - {fov: 180}
                """));
        assertEquals("scenes/v.yaml:2:36: look_at must differ from the camera position", error("""
                views:
                  - {position: [1, 1, 1], look_at: [1, 1, 1]}
                """));
    }
}
