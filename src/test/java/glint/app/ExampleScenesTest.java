package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.input.InputException;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** The example scenes of scenes/ load, say what they show, list views, and render to a picture. */
class ExampleScenesTest {

    private static final Path SCENES = Path.of("scenes");

    static List<Path> scenes() throws IOException {
        try (Stream<Path> files = Files.list(SCENES)) {
            return files.filter(p -> p.toString().endsWith(".yaml")).sorted().toList();
        }
    }

    @Test
    void thereAreAtLeastEightBesidesTheDefault() throws IOException {
        List<Path> scenes = scenes();
        assertTrue(scenes.contains(SCENES.resolve("default.yaml")));
        assertTrue(scenes.size() >= 9, "scenes: " + scenes);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void eachStartsWithACommentAndHasViews(Path scene) throws IOException, InputException {
        assertTrue(Files.readString(scene).startsWith("# "), scene + " starts with a comment saying what it shows");
        Scene s = SceneLoader.load(scene);
        if (!scene.getFileName().toString().equals("default.yaml")) {
            assertFalse(s.views().isEmpty(), scene + " has views");
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void eachRendersToAPicture(Path scene, @TempDir Path dir) throws IOException {
        Path png = dir.resolve("out.png");
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = Main.run(new String[] {"--scene", scene.toString(), "--output", png.toString(),
            "--width", "64", "--height", "36", "--spp", "1"}, new PrintWriter(out, true), new PrintWriter(err, true));
        assertEquals(Main.OK, status, () -> "err: " + err);
        // a run over 2 s (a busy machine) shows its steps; nothing else may be printed
        assertEquals(List.of(), err.toString().lines().filter(l -> !l.matches(
                "(reading|preparing) the scene\\.\\.\\.( [0-9]+ s so far)?|(rendering|writing the image): [0-9]+% done, .*")).toList());
        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(64, image.getWidth());
        assertEquals(36, image.getHeight());
        Set<Integer> colours = new HashSet<>();
        for (int y = 0; y < 36; y++) {
            for (int x = 0; x < 64; x++) {
                colours.add(image.getRGB(x, y));
            }
        }
        assertTrue(colours.size() > 50, scene + " shows more than a few flat colours: " + colours.size());
    }
}
