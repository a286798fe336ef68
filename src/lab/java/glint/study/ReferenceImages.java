package glint.study;

import glint.image.FrameBuffer;
import glint.image.ImageWriter;
import glint.image.PfmReader;
import glint.render.RenderScene;
import glint.render.Tracer;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;

/**
 * Converged images of a scene ({@link StudyConfig#pathReference}, {@link StudyConfig#reference}),
 * rendered once and cached as a PFM under a folder (by default target/study-cache), keyed by the
 * scene text, the size and the settings (not by the renderer's code: after a change to it, run with
 * --fresh). They are rendered with the random numbers of frame {@link #FRAME}, which no measured
 * image uses, so that a reference's noise is independent of the noise of the images it measures.
 * PFM holds float32, enough for a reference whose noise is ~1e-3.
 */
public final class ReferenceImages {

    /** The frame index whose random numbers the references use; the measured images use frame 0. */
    public static final int FRAME = 1;

    private final Path cache;
    private final Tracer tracer;
    private final boolean fresh;

    /** With {@code fresh}, every reference is rendered again and overwrites its cached file. */
    public ReferenceImages(Path cache, Tracer tracer, boolean fresh) {
        this.cache = cache;
        this.tracer = tracer;
        this.fresh = fresh;
    }

    /** The image of {@code scene} at {@code config}, from the cache or rendered now (and cached). */
    public FrameBuffer get(StudyScene scene, StudyConfig config, int width, int height) throws IOException {
        Path file = cache.resolve(scene.name() + "-" + width + "x" + height + "-" + key(scene, config, width, height)
                + ".pfm");
        if (!fresh && Files.isRegularFile(file)) {
            return PfmReader.read(file);
        }
        FrameBuffer frame = new FrameBuffer(width, height);
        long start = System.nanoTime();
        tracer.render(RenderScene.compile(scene.scene(), config.settings()), frame, config.samples(), FRAME,
                FrameTimer.DIVIDER);
        System.out.printf(java.util.Locale.ROOT, "  rendered reference %s (%s) in %.1f s%n", scene.name(), config,
                (System.nanoTime() - start) / 1e9);
        Files.createDirectories(cache);
        ImageWriter.writePfm(frame, file);
        return PfmReader.read(file); // exactly what a later run will read
    }

    private static String key(StudyScene scene, StudyConfig config, int width, int height) {
        try {
            MessageDigest sha = MessageDigest.getInstance("SHA-256");
            sha.update(scene.text().getBytes(StandardCharsets.UTF_8));
            sha.update((config.settings() + "|" + config.samples() + "|" + width + "x" + height + "|frame " + FRAME)
                    .getBytes(StandardCharsets.UTF_8));
            return HexFormat.of().formatHex(sha.digest()).substring(0, 12);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
