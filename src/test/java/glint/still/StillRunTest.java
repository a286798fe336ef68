package glint.still;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.image.FrameBuffer;
import glint.image.PfmReader;
import glint.render.LightTransport;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Shading;
import glint.scenefile.SceneLoader;
import java.io.IOException;
import java.io.InterruptedIOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The one still pipeline both routes use, step by step on this thread: the hidden files made before the
 * work and renamed when complete, a cancel at any step deleting them at once and excluding the rename,
 * a refusal before the work leaving nothing behind, and the words a failure is said in.
 */
class StillRunTest {

    private static final String SCENE = """
            camera: {position: [0, 1, -4], look_at: [0, 1, 0]}
            objects:
              - {type: sphere, center: [0, 1, 0], radius: 1}
            lights:
              - {type: point, position: [2, 4, -3]}
            """;
    @TempDir
    Path dir;

    private final Config config = Config.defaults().withSize(16, 12).withSamples(1).withThreads(2);

    private RenderScene scene() throws Exception {
        return RenderScene.compile(SceneLoader.parse("ball.yaml", SCENE), config.renderSettings());
    }

    private List<String> files() throws IOException {
        try (Stream<Path> list = Files.list(dir)) {
            return list.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    private long hiddenFiles() throws IOException {
        return files().stream().filter(name -> name.startsWith(".") && name.endsWith(".part")).count();
    }

    @Test
    void theHiddenFilesAreMadeBeforeTheWorkAndRenamedWhenBothImagesAreComplete() throws Exception {
        Path png = dir.resolve("ball.png"), pfm = dir.resolve("ball.pfm");
        try (StillRun still = StillRun.open(List.of(png, pfm), List.of(), "still")) {
            assertEquals(2, hiddenFiles(), files()::toString);
            assertEquals(2, files().size(), "nothing else yet");
            FrameBuffer frame = still.render(scene(), config, StillRun.Steps.NONE);
            assertEquals(100, still.percentRendered(), "every tile rendered");
            assertEquals(0, still.percentWritten());
            assertFalse(still.writing());
            still.write(frame, StillRun.Steps.NONE);
            assertTrue(still.writing());
            assertEquals(100, still.percentWritten(), "both files written");
            assertEquals(List.of("ball.pfm", "ball.png"), files());
            assertFalse(still.cancel(), "too late: the images are in place");
            assertArrayEquals(frame.rgb(), PfmReader.read(pfm).rgb());
            assertEquals(16, ImageIO.read(png.toFile()).getWidth());
        }
        assertEquals(List.of("ball.pfm", "ball.png"), files(), "closing keeps what was renamed");
    }

    @Test
    void aCancelBeforeTheRenderDeletesTheHiddenFilesAtOnceAndTheRenderDoesNotStart() throws Exception {
        try (StillRun still = StillRun.open(List.of(dir.resolve("ball.png")), List.of(), "still")) {
            assertEquals(1, hiddenFiles());
            assertTrue(still.cancel());
            assertEquals(List.of(), files(), "deleted by the cancel, not by the close");
            assertThrows(CancellationException.class, () -> still.render(scene(), config, StillRun.Steps.NONE));
        }
        assertEquals(List.of(), files());
    }

    @Test
    void aCancelAfterTheRenderStopsTheWriteAndNothingIsRenamed() throws Exception {
        Path png = dir.resolve("ball.png");
        byte[] old = {1, 2, 3};
        Files.write(png, old);
        try (StillRun still = StillRun.open(List.of(png), List.of(), "still")) {
            FrameBuffer frame = still.render(scene(), config, StillRun.Steps.NONE);
            assertTrue(still.cancel());
            assertThrows(InterruptedIOException.class, () -> still.write(frame, StillRun.Steps.NONE));
        }
        assertEquals(List.of("ball.png"), files(), "no hidden file left");
        assertArrayEquals(old, Files.readAllBytes(png), "the image there before is kept");
    }

    @Test
    void whenTheSecondImageIsRefusedTheFirstsHiddenFileIsDeleted() throws Exception {
        Path missing = dir.resolve("missing");
        StillRefused e = assertThrows(StillRefused.class,
                () -> StillRun.open(List.of(dir.resolve("ball.png"), missing.resolve("ball.pfm")), List.of(), "still"));
        assertEquals("no such folder '" + missing + "'", e.problem());
        assertTrue(e.aboutOutput());
        assertEquals(List.of(), files());
    }

    @Test
    void anOutputThatIsTheSceneIsRefusedWithTheSceneNamed() throws Exception {
        Path scene = Files.writeString(dir.resolve("scene.png"), SCENE);
        Path link = Files.createLink(dir.resolve("hard.png"), scene);
        StillRefused e = assertThrows(StillRefused.class, () -> StillRun.open(List.of(link), List.of(scene), "image"));
        assertEquals("'" + link + "' is the scene file '" + scene + "'; writing the image there would destroy it "
                + "(choose another output name)", e.problem());
        assertEquals(List.of("hard.png", "scene.png"), files());
    }

    @Test
    void theStepsAreTheRenderThenTheWriteEachWithItsFraction() throws Exception {
        StringBuilder steps = new StringBuilder();
        List<Path> images = List.of(dir.resolve("ball.png"), dir.resolve("ball.pfm"));
        try (StillRun still = StillRun.open(images, List.of(), "still")) {
            java.util.function.DoubleSupplier[] last = new java.util.function.DoubleSupplier[1];
            StillRun.Steps record = (name, done) -> {
                steps.append(name).append(';');
                last[0] = done;
            };
            FrameBuffer frame = still.render(scene(), config, record);
            assertEquals(1.0, last[0].getAsDouble(), "every tile done");
            still.write(frame, record);
            assertEquals(1.0, last[0].getAsDouble(), "both images written");
        }
        assertEquals("rendering;writing the image;", steps.toString());
    }

    @Test
    void aFailedWriteNamesTheImageNeverItsHiddenFileInTheSystemsWords() {
        Path png = Path.of("/photos/ball.png");
        assertEquals("cannot write /photos/ball.png: Permission denied",
                new WriteFailure(png, new AccessDeniedException("/photos/.ball.png.3a8.part")).getMessage());
        assertEquals("cannot write /photos/ball.png: No space left on device", new WriteFailure(png,
                new FileSystemException("/photos/.ball.png.3a8.part", null, "No space left on device")).getMessage());
        assertEquals("cannot write /photos/ball.png: File too large",
                new WriteFailure(png, new IOException("File too large")).getMessage());
    }

    @Test
    void theSettingsAreSaidWithOrWithoutTheThreads() {
        Config c = Config.defaults().withSize(800, 600).withSamples(4).withThreads(2);
        assertEquals("800x600, 4 spp, phong, depth 16",
                StillRun.describe(c.withShading(Shading.PHONG).withRecursionMax(16), false));
        assertEquals("800x600, 4 spp, 2 threads, cook-torrance, path, depth 5", StillRun.describe(
                c.withShading(Shading.COOK_TORRANCE).withTransport(LightTransport.PATH).withRecursionMax(5), true));
    }

    @Test
    void theFileSizeLimitIsReadFromTheProcessLimits() throws Exception {
        Path limits = dir.resolve("limits");
        Files.writeString(limits, "Limit                     Soft Limit           Hard Limit           Units\n"
                + "Max cpu time              unlimited            unlimited            seconds\n"
                + "Max file size             51200                unlimited            bytes\n");
        assertEquals(51200, OutputFile.fileSizeLimit(limits));
        Files.writeString(limits, "Max file size             unlimited            unlimited            bytes\n");
        assertEquals(Long.MAX_VALUE, OutputFile.fileSizeLimit(limits));
        assertEquals(Long.MAX_VALUE, OutputFile.fileSizeLimit(dir.resolve("no such file")));
    }
}
