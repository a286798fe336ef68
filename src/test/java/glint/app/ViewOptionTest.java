package glint.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code --view N} and {@code --view NAME}: a scene's view rendered headless instead of its camera. */
class ViewOptionTest {

    private static final String OBJECTS = """
            lights:
              - {type: point, position: [-3, 5, -4], intensity: 50}
            objects:
              - {type: sphere, center: [0, 1, 0], radius: 1, material: {type: matte, color: [0.8, 0.2, 0.2]}}
              - {type: sphere, center: [2, 0.5, 1], radius: 0.5, material: {type: matte, color: [0.2, 0.8, 0.2]}}
              - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
            """;
    private static final String VIEW_1 = "position: [3, 2, -3], look_at: [0, 1, 0], fov: 50";
    private static final String VIEW_2 = "position: [0, 6, -2], look_at: [0, 0, 0], fov: 70";

    @TempDir
    Path dir;
    private Path config;
    private Path scene;

    private record Result(int status, String out, String err) {
    }

    @BeforeEach
    void files() throws IOException {
        config = Files.writeString(dir.resolve("empty.properties"), "");
        scene = Files.writeString(dir.resolve("views.yaml"), "camera: {position: [0, 1, -4], look_at: [0, 1, 0]}\n"
                + "views:\n  - {name: corner, " + VIEW_1 + "}\n  - {name: from above, " + VIEW_2 + "}\n" + OBJECTS);
    }

    private Result run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        String[] all = new String[args.length + 8];
        System.arraycopy(new String[] {"--config", config.toString(), "--width", "32", "--height", "24", "--spp", "4"},
                0, all, 0, 8);
        System.arraycopy(args, 0, all, 8, args.length);
        int status = Main.run(all, new PrintWriter(out, true), new PrintWriter(err, true));
        return new Result(status, out.toString(), err.toString());
    }

    /** The image of the same objects with {@code camera} as the scene's own camera. */
    private byte[] imageWithCamera(String camera, String name) throws IOException {
        Path other = Files.writeString(dir.resolve(name + ".yaml"), "camera: {" + camera + "}\n" + OBJECTS);
        Path png = dir.resolve(name + ".png");
        Result r = run("--scene", other.toString(), "--output", png.toString());
        assertEquals(0, r.status(), r.err());
        return Files.readAllBytes(png);
    }

    private byte[] imageOfView(String view, String name) throws IOException {
        Path png = dir.resolve(name + ".png");
        Result r = run("--scene", scene.toString(), "--view", view, "--output", png.toString());
        assertEquals(0, r.status(), r.err());
        return Files.readAllBytes(png);
    }

    @Test
    void viewNIsTheImageOfThatViewAsTheScenesCamera() throws IOException {
        assertArrayEquals(imageWithCamera(VIEW_2, "camera2"), imageOfView("2", "view2"));
        assertArrayEquals(imageWithCamera(VIEW_1, "camera1"), imageOfView("1", "view1"));
    }

    @Test
    void aViewByItsNameIsTheViewOfThatNumber() throws IOException {
        assertArrayEquals(imageOfView("2", "by-number"), imageOfView("from above", "by-name"));
    }

    @Test
    void withoutViewTheScenesCameraIsRendered() throws IOException {
        Path png = dir.resolve("camera.png");
        assertEquals(0, run("--scene", scene.toString(), "--output", png.toString()).status());
        assertArrayEquals(imageWithCamera("position: [0, 1, -4], look_at: [0, 1, 0]", "own"), Files.readAllBytes(png));
        assertFalse(java.util.Arrays.equals(Files.readAllBytes(png), imageOfView("1", "other")));
    }

    @Test
    void benchSaysWhichViewItTimes() {
        Result r = run("--scene", scene.toString(), "--view", "from above", "--threads", "1", "--bench", "1");
        assertEquals(0, r.status(), r.err());
        assertEquals("timing 1 frame of " + scene + ", view 2 'from above' (32x24, 4 spp, 1 threads, cook-torrance, "
                + "depth 16)", r.out().lines().findFirst().orElse(""));
    }

    /** A view's name is scene text: on standard output it is quoted and escaped, never a line break or a terminal's escape. */
    @Test
    void benchPrintsAViewsNameEscaped() throws IOException {
        Path odd = Files.writeString(dir.resolve("odd.yaml"), "views:\n  - {name: \"clear\\e[2J\\nwrote x.png\", "
                + VIEW_1 + "}\n" + OBJECTS);
        Result r = run("--scene", odd.toString(), "--view", "1", "--threads", "1", "--bench", "1");
        assertEquals(0, r.status(), r.err());
        assertEquals("timing 1 frame of " + odd + ", view 1 'clear\\u001b[2J\\nwrote x.png' (32x24, 4 spp, 1 threads, "
                + "cook-torrance, depth 16)", r.out().lines().findFirst().orElse(""));
        assertEquals(3, r.out().lines().count(), r.out());
    }

    private void assertRefused(String expected, String... args) {
        Path png = dir.resolve("refused.png");
        String[] all = java.util.Arrays.copyOf(args, args.length + 2);
        all[args.length] = "--output";
        all[args.length + 1] = png.toString();
        Result r = run(all);
        assertEquals(Main.BAD_INPUT, r.status(), r.err());
        assertEquals(expected + System.lineSeparator(), r.err());
        assertFalse(Files.exists(png));
    }

    @Test
    void aNumberBeyondTheViewsListsThem() {
        assertRefused("glint: --view 3: '" + scene + "' has 2 views, from 1 to 2: 1 'corner', 2 'from above'",
                "--scene", scene.toString(), "--view", "3");
        assertRefused("glint: --view 0: '" + scene + "' has 2 views, from 1 to 2: 1 'corner', 2 'from above'",
                "--scene", scene.toString(), "--view", "0");
    }

    @Test
    void aMistypedNameIsSuggested() {
        assertRefused("glint: --view 'from abov': '" + scene + "' has no view of that name (did you mean 'from above'?)",
                "--scene", scene.toString(), "--view", "from abov");
    }

    @Test
    void aNameLikeNoneListsTheViews() {
        assertRefused("glint: --view 'sideways': '" + scene + "' has no view of that name; its 2 views: 1 'corner', "
                + "2 'from above'", "--scene", scene.toString(), "--view", "sideways");
    }

    @Test
    void aSceneWithoutViewsSaysSo() throws IOException {
        Path plain = Files.writeString(dir.resolve("plain.yaml"), OBJECTS);
        assertRefused("glint: --view 1: '" + plain + "' has no views (a scene lists them under views:, "
                + "docs/scene-format.md#views)", "--scene", plain.toString(), "--view", "1");
    }

    @Test
    void theWindowPointsToTheKeysAndTheHeadlessModes() {
        Result r = run("--scene", scene.toString(), "--view", "2");
        assertEquals(Main.BAD_INPUT, r.status());
        assertEquals("glint: --view renders headless: add --output FILE.png or --bench N (in the window, keys 1 to 9 "
                + "go to the scene's views)" + System.lineSeparator(), r.err());
        assertTrue(r.out().isEmpty());
    }
}
