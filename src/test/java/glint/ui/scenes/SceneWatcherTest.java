package glint.ui.scenes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.input.InputException;
import glint.scene.Scene;
import glint.scene.SceneLimits;
import glint.scene.SceneLoader;
import glint.ui.Poll;
import glint.ui.TestScenes;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The scene watcher never loads a file that is half written: a change is loaded only once it reads the
 * same for one period. The dangerous half is one that is itself a valid scene (the objects cut off after
 * the first), so the scenes here are cut just there.
 */
class SceneWatcherTest {

    @TempDir
    Path dir;

    private Path file;
    private SceneSource source;
    private SceneWatcher watcher;
    private final Recorder recorder = new Recorder();

    /** Everything the watcher reported, in order. */
    static final class Recorder implements SceneWatcher.Listener {

        private final List<Object> reports = new ArrayList<>();

        @Override
        public synchronized void loaded(Scene scene) {
            reports.add(scene);
        }

        @Override
        public synchronized void failed(InputException error) {
            reports.add(error);
        }

        synchronized List<Object> reports() {
            return List.copyOf(reports);
        }
    }

    @BeforeEach
    void open() throws IOException {
        file = Files.writeString(dir.resolve("scene.yaml"), TestScenes.sphere(0.1, 0.2, 0.3));
        source = new SceneSource(file, () -> {
            throw new AssertionError("no config read");
        });
        watcher = new SceneWatcher(source);
    }

    @AfterEach
    void close() {
        watcher.close();
    }

    /** The scene's text up to (without) its last object: a valid scene with one object fewer. */
    private static String firstHalf(String scene) {
        return scene.substring(0, scene.lastIndexOf("  - {type: plane"));
    }

    @Test
    void theFirstHalfOfASceneIsItselfAValidScene() throws InputException {
        String whole = TestScenes.sphere(0.9, 0.1, 0.1);
        assertEquals(2, SceneLoader.parse("whole", whole).objects().size());
        assertEquals(1, SceneLoader.parse("half", firstHalf(whole)).objects().size(), "the danger: it loads");
    }

    @Test
    void aFileWrittenInTwoHalvesIsLoadedOnlyWhole() throws IOException {
        watcher.listen(recorder);
        String whole = TestScenes.sphere(0.9, 0.1, 0.1);
        Files.writeString(file, firstHalf(whole));
        watcher.poll(); // reads the half: maybe still being written
        assertEquals(List.of(), recorder.reports());
        Files.writeString(file, whole);
        watcher.poll(); // changed again
        assertEquals(List.of(), recorder.reports());
        watcher.poll(); // the same for a period: loaded
        List<Object> reports = recorder.reports();
        assertEquals(1, reports.size(), reports.toString());
        Scene loaded = (Scene) reports.get(0);
        assertEquals(2, loaded.objects().size());
        watcher.poll();
        assertEquals(1, recorder.reports().size(), "reported once");
    }

    @Test
    void aChangeUndoneWithinAPeriodIsNotReported() throws IOException {
        watcher.listen(recorder);
        String original = Files.readString(file);
        Files.writeString(file, "");
        watcher.poll();
        Files.writeString(file, original);
        watcher.poll();
        watcher.poll();
        assertEquals(List.of(), recorder.reports());
    }

    @Test
    void aWriterPausingHalfWayNeverShowsAHalfScene() throws Exception {
        watcher.start(recorder);
        int rounds = 8;
        for (int round = 1; round <= rounds; round++) {
            String whole = TestScenes.sphere(round / 10.0, 0.5, 0.5);
            byte[] bytes = whole.getBytes(StandardCharsets.UTF_8);
            int half = firstHalf(whole).length();
            try (OutputStream out = Files.newOutputStream(file)) { // truncates, writes in place
                out.write(bytes, 0, half);
                out.flush();
                Thread.sleep(SceneWatcher.PERIOD_MILLIS * 2 / 5); // an editor or a network copy stalls
                out.write(bytes, half, bytes.length - half);
            }
            int expected = round;
            Poll.until(() -> recorder.reports().size() >= expected, 5_000, "round " + round + " loaded");
        }
        List<Object> reports = recorder.reports();
        assertEquals(rounds, reports.size(), "each save once, nothing in between: " + reports);
        for (int i = 0; i < rounds; i++) {
            Scene scene = (Scene) reports.get(i);
            assertEquals(2, scene.objects().size(), "round " + (i + 1) + " loaded whole");
            assertEquals((i + 1) / 10.0, scene.background().x(), 1e-12);
        }
    }

    /** Version {@code n} of a scene whose versions differ only near the end: their first halves are the same bytes. */
    private static String version(int n) {
        return TestScenes.sphere(0.5, 0.5, 0.5) + String.format(java.util.Locale.ROOT,
                "  - {type: sphere, center: [2, 1, 0], radius: %.3f}%n", 0.5 + n / 1000.0);
    }

    /** Truncates the file and writes the first half of {@code text}, then, {@code pauseMillis} later, the rest. */
    private void saveInTwoHalves(String text, long pauseMillis) throws Exception {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        int half = bytes.length / 2; // mid-line: a YAML error
        try (OutputStream out = Files.newOutputStream(file)) {
            out.write(bytes, 0, half);
            out.flush();
            Thread.sleep(pauseMillis); // the writer's own pace, as the user's editor or copy goes
            out.write(bytes, half, bytes.length - half);
        }
    }

    /**
     * Two reads a period apart can find the same bytes while the file keeps changing: the first half of one
     * save and the first half of a later one, when the saves differ only after the middle. The file's
     * modification time tells them apart, so that half is not loaded.
     */
    @Test
    void theSameHalfOfTwoSavesIsNotTakenForAFileThatStayedTheSame() throws Exception {
        watcher.listen(recorder);
        String half = version(1).substring(0, version(1).getBytes(StandardCharsets.UTF_8).length / 2);
        assertTrue(version(2).startsWith(half), "the two saves' first halves are the same bytes");
        Files.writeString(file, half);
        watcher.poll(); // the first save's half
        Thread.sleep(30); // the saves' own pace
        Files.writeString(file, version(1));
        Thread.sleep(10);
        Files.writeString(file, half); // the next save has written its first half, the same bytes...
        watcher.poll(); // ... when the watcher reads again
        assertEquals(List.of(), recorder.reports(), "nothing loaded: the file changed between the two reads");
        Files.writeString(file, version(2));
        watcher.poll();
        watcher.poll();
        List<Object> reports = recorder.reports();
        assertEquals(1, reports.size(), reports.toString());
        assertEquals(3, ((Scene) reports.get(0)).objects().size(), "the last save, whole");
    }

    /** 50 valid saves in 2 s, each written in two halves 30 ms apart: never an error, and the last one loads. */
    @Test
    void fiftySavesInTwoSecondsEachInTwoHalvesNeverShowAHalfFile() throws Exception {
        watcher.start(recorder);
        for (int n = 1; n <= 50; n++) {
            saveInTwoHalves(version(n), 30);
            Thread.sleep(10);
        }
        Poll.until(() -> !recorder.reports().isEmpty() && recorder.reports().get(recorder.reports().size() - 1)
                instanceof Scene last && last.objects().size() == 3, 5_000, () -> "the last save loaded: "
                + recorder.reports());
        for (Object report : recorder.reports()) {
            assertTrue(report instanceof Scene, () -> "only whole saves reported: " + recorder.reports());
        }
        List<Object> reports = recorder.reports();
        String lastRadius = String.valueOf(((Scene) reports.get(reports.size() - 1)).objects().get(2));
        assertTrue(lastRadius.contains("0.55"), lastRadius);
    }

    /** Memory running out on the watcher's thread (here, in what it reports to) does not end the watching. */
    @Test
    void theWatcherGoesOnAfterMemoryRanOutOnItsThread() throws Exception {
        boolean[] thrown = {false};
        watcher.start(new SceneWatcher.Listener() {
            @Override
            public void loaded(Scene scene) {
                synchronized (thrown) {
                    if (!thrown[0]) {
                        thrown[0] = true;
                        throw new OutOfMemoryError("Java heap space");
                    }
                }
                recorder.loaded(scene);
            }

            @Override
            public void failed(InputException error) {
                recorder.failed(error);
            }
        });
        TestScenes.replace(file, TestScenes.sphere(0.7, 0.5, 0.5));
        Poll.until(() -> !recorder.reports().isEmpty(), 5_000, "the failure reported");
        assertEquals(file + ": cannot watch: java.lang.OutOfMemoryError: Java heap space",
                ((InputException) recorder.reports().get(0)).getMessage());
        TestScenes.replace(file, TestScenes.sphere(0.3, 0.5, 0.5));
        Poll.until(() -> recorder.reports().size() >= 2, 5_000, () -> "the next save loaded: " + recorder.reports());
        assertEquals(0.3, ((Scene) recorder.reports().get(1)).background().x(), 1e-12);
    }

    @Test
    void theSceneIsReadWithinTheSourcesLimits() throws IOException {
        watcher.listen(recorder);
        source.limits(new SceneLimits(SceneLimits.DEFAULT.maxFileBytes(), 1, SceneLimits.DEFAULT.maxLights()));
        Files.writeString(file, TestScenes.sphere(0.5, 0.5, 0.5));
        watcher.poll();
        watcher.poll();
        InputException e = (InputException) recorder.reports().get(0);
        assertTrue(e.getMessage().endsWith("too many objects: more than 1 (config key max_objects)"), e.getMessage());
    }

    @Test
    void aFileOverTheSizeLimitIsRefusedWithoutReadingIt() throws IOException {
        watcher.listen(recorder);
        source.limits(new SceneLimits(1000, SceneLimits.DEFAULT.maxObjects(), SceneLimits.DEFAULT.maxLights()));
        Files.writeString(file, TestScenes.sphere(0.5, 0.5, 0.5) + "#".repeat(5000) + "\n");
        watcher.poll();
        watcher.poll();
        InputException e = (InputException) recorder.reports().get(0);
        assertTrue(e.getMessage().endsWith("(config key max_scene_bytes)"), e.getMessage());
        watcher.poll();
        assertEquals(1, recorder.reports().size(), "reported once");
    }

    @Test
    void aVanishedFileIsReportedOnlyIfItStaysAway() throws IOException {
        watcher.listen(recorder);
        String original = Files.readString(file);
        Files.delete(file);
        watcher.poll(); // an editor saving by rename: gone for a moment
        Files.writeString(file, original);
        watcher.poll();
        watcher.poll();
        assertEquals(List.of(), recorder.reports());
        Files.delete(file);
        watcher.poll();
        watcher.poll();
        assertEquals(file + ": no such file", ((InputException) recorder.reports().get(0)).getMessage());
    }

    @Test
    void aSceneReplacedByAFifoIsReportedWithoutBlockingAndTheNextGoodFileLoads() throws Exception {
        watcher.listen(recorder);
        Files.delete(file);
        Process mkfifo = new ProcessBuilder("mkfifo", file.toString()).start();
        assertEquals(0, mkfifo.waitFor(), "mkfifo");
        assertTimeoutPreemptively(Duration.ofSeconds(20), () -> {
            watcher.poll(); // opening a FIFO for reading would block until a writer comes: never opened
            watcher.poll();
        });
        assertEquals(file + ": is not a regular file (a pipe, device or socket); expected a file on disk",
                ((InputException) recorder.reports().get(0)).getMessage());
        Files.delete(file);
        Files.writeString(file, TestScenes.sphere(0.3, 0.6, 0.9));
        watcher.poll();
        watcher.poll();
        assertEquals(0.6, ((Scene) recorder.reports().get(1)).background().y(), 1e-12, "the watcher still works");
    }
}
