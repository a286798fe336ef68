package glint.ui.scenes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.input.InputException;
import glint.scene.Scene;
import glint.scenefile.SceneLimits;
import glint.scenefile.SceneLoader;
import glint.ui.Poll;
import glint.ui.TestScenes;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.FileTime;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.TreeMap;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The scene watcher never loads a file that is half written: a change is loaded only once two reads a
 * period apart find the same bytes and the same modification time. The dangerous half is one that is
 * itself a valid scene (the objects cut off after the first), so the scenes here are cut just there. The
 * test says when a period has passed ({@link ManualTimer}), and sets the files' modification times itself:
 * no test waits for the watcher's thread but the one that checks that thread.
 */
class SceneWatcherTest {

    @TempDir
    Path dir;

    private Path file;
    private SceneSource source;
    private final ManualTimer timer = new ManualTimer();
    private SceneWatcher watcher;
    private final Recorder recorder = new Recorder();

    /** Everything the watcher reported, in order, and on which thread. */
    static final class Recorder implements SceneWatcher.Listener {

        private final List<Object> reports = new ArrayList<>();
        private final List<String> threads = new ArrayList<>();

        @Override
        public synchronized void loaded(Scene scene) {
            reports.add(scene);
            threads.add(Thread.currentThread().getName());
        }

        @Override
        public synchronized void failed(InputException error) {
            reports.add(error);
            threads.add(Thread.currentThread().getName());
        }

        synchronized List<Object> reports() {
            return List.copyOf(reports);
        }

        synchronized List<String> threads() {
            return List.copyOf(threads);
        }
    }

    @BeforeEach
    void open() throws IOException {
        file = Files.writeString(dir.resolve("scene.yaml"), TestScenes.sphere(0.1, 0.2, 0.3));
        source = new SceneSource(file, () -> {
            throw new AssertionError("no config read");
        });
        watcher = new SceneWatcher(source, timer);
    }

    @AfterEach
    void close() {
        watcher.close();
    }

    /** The scene's text up to (without) its last object: a valid scene with one object fewer. */
    private static String firstHalf(String scene) {
        return scene.substring(0, scene.lastIndexOf("  - {type: plane"));
    }

    /** Writes the file in place (truncated, then written) and gives it the modification time {@code millis}. */
    private void write(String text, long millis) throws IOException {
        Files.writeString(file, text);
        Files.setLastModifiedTime(file, FileTime.fromMillis(millis));
    }

    @Test
    void theFirstHalfOfASceneIsItselfAValidScene() throws InputException {
        String whole = TestScenes.sphere(0.9, 0.1, 0.1);
        assertEquals(2, SceneLoader.parse("whole", whole).objects().size());
        assertEquals(1, SceneLoader.parse("half", firstHalf(whole)).objects().size(), "the danger: it loads");
    }

    @Test
    void theFileIsReadEveryPeriodAndAChangeLoadedWhenTwoReadsAPeriodApartAgree() throws IOException {
        watcher.start(recorder);
        assertEquals(250, timer.periodMillis(), "four reads a second");
        assertEquals(SceneWatcher.PERIOD_MILLIS, timer.periodMillis());
        timer.tick();
        assertEquals(List.of(), recorder.reports(), "unchanged: nothing to report");
        write(TestScenes.sphere(0.9, 0.1, 0.1), 1_000_000);
        timer.tick(); // the change, read once: maybe still being written
        assertEquals(List.of(), recorder.reports());
        timer.tick(); // a period later, the same bytes and time: loaded
        assertEquals(1, recorder.reports().size(), recorder.reports().toString());
        assertEquals(0.9, ((Scene) recorder.reports().get(0)).background().x(), 1e-12);
        timer.tick();
        timer.tick();
        assertEquals(1, recorder.reports().size(), "reported once");
    }

    @Test
    void aFileWrittenInTwoHalvesIsLoadedOnlyWhole() throws IOException {
        watcher.start(recorder);
        String whole = TestScenes.sphere(0.9, 0.1, 0.1);
        write(firstHalf(whole), 1_000_000);
        timer.tick(); // reads the half: maybe still being written
        assertEquals(List.of(), recorder.reports());
        write(whole, 1_000_030);
        timer.tick(); // changed again
        assertEquals(List.of(), recorder.reports());
        timer.tick(); // the same for a period: loaded
        List<Object> reports = recorder.reports();
        assertEquals(1, reports.size(), reports.toString());
        Scene loaded = (Scene) reports.get(0);
        assertEquals(2, loaded.objects().size());
        timer.tick();
        assertEquals(1, recorder.reports().size(), "reported once");
    }

    @Test
    void aChangeUndoneWithinAPeriodIsNotReported() throws IOException {
        watcher.start(recorder);
        String original = Files.readString(file);
        Files.writeString(file, "");
        timer.tick();
        Files.writeString(file, original);
        timer.tick();
        timer.tick();
        assertEquals(List.of(), recorder.reports());
    }

    /**
     * A writer that stops half way (an editor, a network copy) for less than a period is read at most once
     * in the pause, so its half is never loaded: each save, written in place through one stream, is reported
     * once and whole.
     */
    @Test
    void aWriterPausingHalfWayForLessThanAPeriodNeverShowsAHalfScene() throws Exception {
        watcher.start(recorder);
        int rounds = 8;
        for (int round = 1; round <= rounds; round++) {
            String whole = TestScenes.sphere(round / 10.0, 0.5, 0.5);
            byte[] bytes = whole.getBytes(StandardCharsets.UTF_8);
            int half = firstHalf(whole).length();
            try (OutputStream out = Files.newOutputStream(file)) { // truncates, writes in place
                out.write(bytes, 0, half);
                out.flush();
                timer.tick(); // the one read that falls in the pause
                out.write(bytes, half, bytes.length - half);
            }
            timer.tick();
            timer.tick();
            assertEquals(round, recorder.reports().size(), "round " + round + " loaded");
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
        return TestScenes.sphere(0.5, 0.5, 0.5) + String.format(Locale.ROOT,
                "  - {type: sphere, center: [2, 1, 0], radius: %.3f}%n", 0.5 + n / 1000.0);
    }

    /** The first half of {@code text}'s bytes: mid-line, a YAML error. */
    private static byte[] half(String text) {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        return java.util.Arrays.copyOf(bytes, bytes.length / 2);
    }

    /**
     * Two reads a period apart can find the same bytes while the file keeps changing: the first half of one
     * save and the first half of a later one, when the saves differ only after the middle. The file's
     * modification time tells them apart, so that half is not loaded.
     */
    @Test
    void theSameHalfOfTwoSavesIsNotTakenForAFileThatStayedTheSame() throws Exception {
        watcher.start(recorder);
        assertTrue(version(2).startsWith(new String(half(version(1)), StandardCharsets.UTF_8)),
                "the two saves' first halves are the same bytes");
        Files.write(file, half(version(1)));
        Files.setLastModifiedTime(file, FileTime.fromMillis(1_000_000));
        timer.tick(); // the first save's half
        write(version(1), 1_000_030);
        Files.write(file, half(version(2))); // the next save has written its first half, the same bytes...
        Files.setLastModifiedTime(file, FileTime.fromMillis(1_000_040));
        timer.tick(); // ... when the watcher reads again
        assertEquals(List.of(), recorder.reports(), "nothing loaded: the file changed between the two reads");
        write(version(2), 1_000_070);
        timer.tick();
        timer.tick();
        List<Object> reports = recorder.reports();
        assertEquals(1, reports.size(), reports.toString());
        assertEquals(3, ((Scene) reports.get(0)).objects().size(), "the last save, whole");
    }

    /**
     * 50 valid saves in 2 s, each written in two halves 30 ms apart (the first half a YAML error, and the same
     * bytes in every save), read every 250 ms: never an error, and the last one loads. The time line is the
     * test's: each write gets the modification time of its moment, and the watcher reads at each period.
     */
    @Test
    void fiftySavesInTwoSecondsEachInTwoHalvesNeverShowAHalfFile() throws Exception {
        watcher.start(recorder);
        long origin = 1_000_000;
        TreeMap<Long, List<String>> timeLine = new TreeMap<>(); // ms from the origin: what happens then
        for (int n = 1; n <= 50; n++) {
            timeLine.computeIfAbsent(40L * n, t -> new ArrayList<>()).add("half " + n);
            timeLine.computeIfAbsent(40L * n + 30, t -> new ArrayList<>()).add("rest " + n);
        }
        long end = 40L * 50 + 30 + 2 * SceneWatcher.PERIOD_MILLIS;
        for (long t = SceneWatcher.PERIOD_MILLIS; t <= end; t += SceneWatcher.PERIOD_MILLIS) {
            timeLine.computeIfAbsent(t, x -> new ArrayList<>()).add("read");
        }
        int halvesRead = 0;
        boolean half = false;
        for (var moment : timeLine.entrySet()) {
            for (String event : moment.getValue()) {
                String[] words = event.split(" ");
                if (words[0].equals("read")) {
                    halvesRead += half ? 1 : 0;
                    timer.tick();
                    continue;
                }
                String text = version(Integer.parseInt(words[1]));
                if (words[0].equals("half")) {
                    Files.write(file, half(text));
                } else {
                    byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
                    Files.write(file, java.util.Arrays.copyOfRange(bytes, bytes.length / 2, bytes.length),
                            StandardOpenOption.APPEND);
                }
                half = words[0].equals("half");
                Files.setLastModifiedTime(file, FileTime.fromMillis(origin + moment.getKey()));
            }
        }
        assertTrue(halvesRead >= 2, "reads fell on half files, the same bytes each time: " + halvesRead);
        List<Object> reports = recorder.reports();
        for (Object report : reports) {
            assertTrue(report instanceof Scene, () -> "only whole saves reported: " + reports);
        }
        assertTrue(!reports.isEmpty(), "the last save loaded");
        String lastRadius = String.valueOf(((Scene) reports.get(reports.size() - 1)).objects().get(2));
        assertTrue(lastRadius.contains("0.55"), lastRadius);
    }

    /** Memory running out in a read (here, in what the watcher reports to) is reported, and the reads go on. */
    @Test
    void theWatcherGoesOnAfterMemoryRanOutInARead() throws Exception {
        boolean[] thrown = {false};
        watcher.start(new SceneWatcher.Listener() {
            @Override
            public void loaded(Scene scene) {
                if (!thrown[0]) {
                    thrown[0] = true;
                    throw new OutOfMemoryError("Java heap space");
                }
                recorder.loaded(scene);
            }

            @Override
            public void failed(InputException error) {
                recorder.failed(error);
            }
        });
        write(TestScenes.sphere(0.7, 0.5, 0.5), 1_000_000);
        timer.tick();
        timer.tick();
        assertEquals(file + ": cannot watch: java.lang.OutOfMemoryError: Java heap space",
                ((InputException) recorder.reports().get(0)).getMessage());
        write(TestScenes.sphere(0.3, 0.5, 0.5), 1_000_500);
        timer.tick();
        timer.tick();
        assertEquals(2, recorder.reports().size(), () -> "the next save loaded: " + recorder.reports());
        assertEquals(0.3, ((Scene) recorder.reports().get(1)).background().x(), 1e-12);
    }

    /** The watcher of the program reads on a thread of its own, and closing it stops its timer. */
    @Test
    void theProgramsWatcherReadsOnAThreadOfItsOwn() throws Exception {
        SceneWatcher own = new SceneWatcher(source);
        try {
            own.start(recorder);
            TestScenes.replace(file, TestScenes.sphere(0.7, 0.5, 0.5));
            Poll.until(() -> !recorder.reports().isEmpty(), 10_000, "the save loaded");
            assertEquals(0.7, ((Scene) recorder.reports().get(0)).background().x(), 1e-12);
            assertEquals(List.of("glint-scene-watcher"), recorder.threads());
        } finally {
            own.close();
        }
        watcher.start(recorder);
        watcher.close();
        assertTrue(timer.closed());
    }

    @Test
    void theSceneIsReadWithinTheSourcesLimits() throws IOException {
        watcher.start(recorder);
        source.limits(new SceneLimits(SceneLimits.DEFAULT.maxFileBytes(), 1, SceneLimits.DEFAULT.maxLights()));
        Files.writeString(file, TestScenes.sphere(0.5, 0.5, 0.5));
        timer.tick();
        timer.tick();
        InputException e = (InputException) recorder.reports().get(0);
        assertTrue(e.getMessage().endsWith("too many objects: more than 1 (config key max_objects)"), e.getMessage());
    }

    @Test
    void aFileOverTheSizeLimitIsRefusedWithoutReadingIt() throws IOException {
        watcher.start(recorder);
        source.limits(new SceneLimits(1000, SceneLimits.DEFAULT.maxObjects(), SceneLimits.DEFAULT.maxLights()));
        Files.writeString(file, TestScenes.sphere(0.5, 0.5, 0.5) + "#".repeat(5000) + "\n");
        timer.tick();
        timer.tick();
        InputException e = (InputException) recorder.reports().get(0);
        assertTrue(e.getMessage().endsWith("(config key max_scene_bytes)"), e.getMessage());
        timer.tick();
        assertEquals(1, recorder.reports().size(), "reported once");
    }

    @Test
    void aVanishedFileIsReportedOnlyIfItStaysAway() throws IOException {
        watcher.start(recorder);
        String original = Files.readString(file);
        Files.delete(file);
        timer.tick(); // an editor saving by rename: gone for a moment
        Files.writeString(file, original);
        timer.tick();
        timer.tick();
        assertEquals(List.of(), recorder.reports());
        Files.delete(file);
        timer.tick();
        timer.tick();
        assertEquals(file + ": no such file", ((InputException) recorder.reports().get(0)).getMessage());
    }

    @Test
    void aSceneReplacedByAFifoIsReportedWithoutBlockingAndTheNextGoodFileLoads() throws Exception {
        watcher.start(recorder);
        Files.delete(file);
        Process mkfifo = new ProcessBuilder("mkfifo", file.toString()).start();
        assertEquals(0, mkfifo.waitFor(), "mkfifo");
        assertTimeoutPreemptively(Duration.ofSeconds(20), () -> {
            timer.tick(); // opening a FIFO for reading would block until a writer comes: never opened
            timer.tick();
        });
        assertEquals(file + ": is not a regular file (a pipe, device or socket); expected a file on disk",
                ((InputException) recorder.reports().get(0)).getMessage());
        Files.delete(file);
        Files.writeString(file, TestScenes.sphere(0.3, 0.6, 0.9));
        timer.tick();
        timer.tick();
        assertEquals(0.6, ((Scene) recorder.reports().get(1)).background().y(), 1e-12, "the watcher still works");
    }
}
