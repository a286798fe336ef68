package glint.study;

import glint.image.FrameBuffer;
import glint.image.PfmReader;
import glint.input.InputException;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Checks the study's physically based reference against the images of an independent path tracer
 * (src/test/resources/reference-pt, whose README gives the bounds a correct 256-sample render at
 * 400 x 300 meets): Glint's path tracer at the README's settings, the study's converged reference
 * against the independent image averaged to the study's size, and Whitted's converged image the same
 * way, for scale.
 */
final class PhysicsValidation {

    /** The README's bounds for one scene: mean FLIP, relMSE, mean 8-bit error. */
    record Bound(String scene, double flip, double relMse, double levels) {
    }

    /** The README's table. */
    static final List<Bound> BOUNDS = List.of(new Bound("bounce-box", 0.020, 3.3e-4, 1.24),
            new Bound("sky-and-sun", 0.0091, 1.1e-4, 0.55));
    /** The README's settings: 400 x 300, 256 samples, depth 64, the path tracer, cook-torrance. */
    static final int WIDTH = 400, HEIGHT = 300, SAMPLES = 256;

    static final String HEADER = "| scene | image | relMSE | 8-bit error | FLIP |\n|---|---|--:|--:|--:|\n";

    private PhysicsValidation() {
    }

    static Path folder(Path root) {
        return root.resolve("src/test/resources/reference-pt");
    }

    /** The scenes with an independent reference, each with its image. */
    static List<StudyScene> scenes(Path root) throws IOException, InputException {
        List<StudyScene> scenes = new ArrayList<>();
        for (Bound b : BOUNDS) {
            scenes.add(StudyScene.load(b.scene(), folder(root).resolve(b.scene() + ".yaml"),
                    folder(root).resolve(b.scene() + ".pfm")));
        }
        return scenes;
    }

    static Bound bound(String scene) {
        for (Bound b : BOUNDS) {
            if (b.scene().equals(scene)) {
                return b;
            }
        }
        throw new IllegalArgumentException("no independent reference for " + scene);
    }

    /**
     * The table's rows for one scene: Glint at the README's settings (if {@code readmeSettings}), the
     * study's path reference and Whitted's converged image, each against the independent image
     * (averaged to their size).
     */
    static String rows(StudyScene scene, FrameBuffer pathReference, int pathSamples, FrameBuffer whittedReference,
                       ReferenceImages references, boolean readmeSettings) throws IOException {
        FrameBuffer independent = PfmReader.read(scene.independentReference());
        Bound bound = bound(scene.name());
        StringBuilder b = new StringBuilder();
        if (readmeSettings) {
            FrameBuffer readme = references.get(scene, StudyConfig.pathReference(SAMPLES), WIDTH, HEIGHT);
            ImageErrors e = ImageErrors.of(readme, independent);
            b.append(String.format(Locale.ROOT, "| %s | path, the README's settings (%dx%d, %d samples, depth %d) "
                            + "| %s (bound %s) | %.2f (bound %.2f) | %.4f (bound %.4f) |%n", scene.name(), WIDTH, HEIGHT,
                    SAMPLES, StudyConfig.REFERENCE_DEPTH, Numbers.sig3(e.relMse()), Numbers.sci(bound.relMse()),
                    e.levels(), bound.levels(), e.flip(), bound.flip()));
        }
        int factor = WIDTH / pathReference.width();
        FrameBuffer small = ImageErrors.averaged(independent, factor);
        b.append(row(scene.name(), String.format(Locale.ROOT, "the study's reference: path, %dx%d, %d samples, depth %d",
                pathReference.width(), pathReference.height(), pathSamples, StudyConfig.REFERENCE_DEPTH),
                ImageErrors.of(pathReference, small)));
        b.append(row(scene.name(), "Whitted's converged image, the same size", ImageErrors.of(whittedReference, small)));
        return b.toString();
    }

    private static String row(String scene, String image, ImageErrors e) {
        return String.format(Locale.ROOT, "| %s | %s | %s | %.2f | %.4f |%n", scene, image, Numbers.sig3(e.relMse()),
                e.levels(), e.flip());
    }
}
