package glint.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import glint.input.InputException;
import glint.scene.Light;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Every shipped scene in phong reads at the brightness cook-torrance gives it (phong's light term is E / pi):
 * at most 2 % of its pixels clipped (a channel at 1 or above, white before any tone curve), and the default
 * scene's gold ball gold. A lamp seen directly (a sphere light's body) is white in every model; it is left out
 * by rendering each light as a point of the same power (a sun as a direction), which lights the scene alike.
 */
class PhongShippedScenesTest {

    static final int W = 80, H = 60;

    static List<Path> shippedScenes() throws IOException {
        try (Stream<Path> files = Files.list(Path.of("scenes"))) {
            return files.filter(p -> p.toString().endsWith(".yaml")).sorted().toList();
        }
    }

    static FrameBuffer phong(Path file) throws IOException, InputException {
        Scene scene = SceneLoader.load(file);
        List<Light> points = scene.lights().stream().map(l -> l instanceof Light.Point p
                ? (Light) new Light.Point(p.position(), p.color(), p.intensity())
                : l instanceof Light.Directional d ? new Light.Directional(d.direction(), d.color(), d.intensity()) : l)
                .toList();
        Scene unseen = new Scene(scene.camera(), scene.background(), scene.ambient(), points, scene.objects(),
                scene.views(), scene.render());
        return Renders.render(unseen, W, H, 1, 16, Shading.PHONG, 2, 4);
    }

    /** The fraction of pixels with a channel at 1 or above. */
    static double clipped(FrameBuffer frame) {
        int n = 0;
        for (int y = 0; y < frame.height(); y++) {
            for (int x = 0; x < frame.width(); x++) {
                if (frame.get(x, y, 0) >= 1 || frame.get(x, y, 1) >= 1 || frame.get(x, y, 2) >= 1) {
                    n++;
                }
            }
        }
        return n / (double) (frame.width() * frame.height());
    }

    @Test
    void everyShippedSceneInPhongClipsAtMostTwoPercentOfItsPixels() throws Exception {
        StringBuilder report = new StringBuilder();
        boolean ok = true;
        for (Path file : shippedScenes()) {
            double fraction = clipped(phong(file));
            report.append(String.format(java.util.Locale.ROOT, "%s %.2f %%%n", file.getFileName(), 100 * fraction));
            ok &= fraction <= 0.02;
        }
        System.out.print(report);
        assertTrue(ok, "more than 2 % clipped in phong:\n" + report);
    }

    /** The gold ball of the default scene (right of the middle): gold, red above green above blue, not silver. */
    @Test
    void theDefaultScenesGoldStaysGoldInPhong() throws Exception {
        FrameBuffer frame = phong(Path.of("scenes/default.yaml"));
        double r = 0, g = 0, b = 0;
        int n = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                if (isGold(frame, x, y)) {
                    r += frame.get(x, y, 0);
                    g += frame.get(x, y, 1);
                    b += frame.get(x, y, 2);
                    n++;
                }
            }
        }
        System.out.printf("gold pixels %d: mean %.3f %.3f %.3f%n", n, r / n, g / n, b / n);
        assertTrue(n > 40, "the gold ball covers " + n + " pixels");
        assertTrue(r > g && g > 1.5 * b && b < 0.6 * r, "gold: " + r / n + ", " + g / n + ", " + b / n);
    }

    /** Whether a pixel of the default scene lies on its gold ball's disc on screen. */
    private static boolean isGold(FrameBuffer frame, int x, int y) {
        // the ball at [2.2, 1, 0], radius 1, seen from the default camera: found by its pixels' place
        return Math.hypot(x - GOLD_X, y - GOLD_Y) < GOLD_R;
    }

    static final double GOLD_X = 59, GOLD_Y = 27, GOLD_R = 6;
}
