package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import glint.image.Srgb;
import glint.render.RenderScene;
import glint.render.Tracer;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The speed/accuracy study: its verdict read off the front, the 8-bit error and the averaging to a
 * smaller size, the timer's long frames, and a short run of the study on the matte box, whose light
 * Whitted's integrator cannot carry and the path tracer can.
 */
class SpeedAccuracyTest {

    private static Measurement point(StudyConfig config, double cpuMillis, double relMse, double flip) {
        return new Measurement("s", config, cpuMillis, cpuMillis, new ImageErrors(relMse, 0.9, flip, 1));
    }

    @Test
    void thePathWinsFromTheFrontPointAfterWhichTheFrontIsAllPath() {
        Measurement rayCasting = point(StudyConfig.whitted(1, 1), 1, 0.1, 0.3);
        Measurement whitted = point(StudyConfig.whitted(16, 4), 4, 0.05, 0.2);
        Measurement path1 = point(StudyConfig.path(1), 3, 0.2, 0.1);
        Measurement path4 = point(StudyConfig.path(4), 12, 0.03, 0.05);
        Measurement path16 = point(StudyConfig.path(16), 48, 0.008, 0.02);
        List<Measurement> ms = List.of(rayCasting, whitted, path1, path4, path16);
        // relMSE: ray casting, Whitted, then path 4 and 16; FLIP: ray casting, then path 1, 4 and 16
        assertSame(path4, AccuracyReport.pathTakesOver(ms, Measurement::relMse));
        assertSame(path1, AccuracyReport.pathTakesOver(ms, Measurement::flip));
        AccuracyReport.Verdict v = AccuracyReport.verdict("s", ms);
        assertSame(whitted, v.bestWhitted());
        assertSame(path4, v.pathMatching());
        assertEquals("| s | Whitted d16 s4, 4 ms | 5.00e-02 / 0.200 | path s4, 12 ms | path s1, 3 ms | path s4, 12 ms |",
                AccuracyReport.verdictTable(List.of(v)).lines().skip(2).findFirst().orElseThrow());
    }

    @Test
    void thePathDoesNotWinWhileWhittedEndsTheFront() {
        Measurement path = point(StudyConfig.path(4), 2, 0.05, 0.05);
        Measurement whitted = point(StudyConfig.whitted(16, 64), 50, 0.01, 0.01);
        assertNull(AccuracyReport.pathTakesOver(List.of(path, whitted), Measurement::relMse));
        AccuracyReport.Verdict v = AccuracyReport.verdict("s", List.of(path, whitted));
        assertNull(v.pathMatching());
        assertTrue(AccuracyReport.verdictTable(List.of(v)).contains("| not up to path s1024 |"));
    }

    @Test
    void theEightBitErrorIsOnClampedSrgbAndAveragingIsABoxOverEachCell() {
        FrameBuffer grey = new FrameBuffer(1, 1), black = new FrameBuffer(1, 1), bright = new FrameBuffer(1, 1);
        grey.set(0, 0, 0.5, 0.5, 0.5);
        bright.set(0, 0, 2, 1, 7);
        assertEquals(255 * Srgb.encode(0.5), ImageErrors.meanLevels(grey, black), 1e-9);
        assertEquals(187.5, ImageErrors.meanLevels(grey, black), 0.1); // 0.5 linear is sRGB 0.735
        FrameBuffer white = new FrameBuffer(1, 1);
        white.set(0, 0, 1, 1, 1);
        assertEquals(0, ImageErrors.meanLevels(bright, white)); // both clamp to 1

        FrameBuffer image = new FrameBuffer(4, 2);
        for (int x = 0; x < 4; x++) {
            image.set(x, 0, x, 1, 0);
            image.set(x, 1, x + 4, 3, 0);
        }
        FrameBuffer half = ImageErrors.averaged(image, 2);
        assertEquals(2, half.width());
        assertEquals(1, half.height());
        assertEquals((0 + 1 + 4 + 5) / 4.0, half.get(0, 0, 0), 1e-6);
        assertEquals((2 + 3 + 6 + 7) / 4.0, half.get(1, 0, 0), 1e-6);
        assertEquals(2, half.get(1, 0, 1), 1e-6);
    }

    /** A frame at least as long as the timer's threshold is its job's only one; shorter ones are timed every round. */
    @Test
    void aLongFirstFrameIsTheJobsOnlyTimedOne() throws Exception {
        StudyScene scene = StudyScene.load("box", PhysicsValidation.folder(Path.of(".")).resolve("bounce-box.yaml"), null);
        try (Tracer tracer = new Tracer(1)) {
            List<FrameTimer.Job> jobs = List.of(new FrameTimer.Job(
                    RenderScene.compile(scene.scene(), StudyConfig.whitted(1, 1).settings()), new FrameBuffer(16, 12), 1));
            long before = tracer.raysCast();
            tracer.render(jobs.get(0).scene(), jobs.get(0).frame(), 1, 0, 1);
            long oneFrame = tracer.raysCast() - before;
            before = tracer.raysCast();
            new FrameTimer(tracer, 3, 0).median(jobs); // every frame counts as long
            assertEquals(oneFrame, tracer.raysCast() - before);
            before = tracer.raysCast();
            new FrameTimer(tracer, 3, Double.POSITIVE_INFINITY).median(jobs);
            assertEquals(4 * oneFrame, tracer.raysCast() - before);
        }
    }

    /**
     * The short run on the matte box: the path tracer's error falls with every quadrupling of its
     * samples, Whitted's best stays far above it (it has no light that bounces), the path takes the
     * front over, and the run writes its chart and its tables.
     */
    @Test
    void aShortRunOnTheMatteBoxFindsWhatPhysicsSaysAndWritesItsChartAndTables(@TempDir Path dir) throws Exception {
        SpeedAccuracy.Plan plan = SpeedAccuracy.Plan.of(true, 1);
        List<StudyScene> scenes = SpeedAccuracy.select(SpeedAccuracy.scenes(Path.of(".")), List.of("bounce-box"));
        List<SpeedAccuracy.SceneResult> results = SpeedAccuracy.run(plan, scenes, dir.resolve("cache"), 2, false);
        List<Measurement> physics = results.get(0).physics();
        List<Double> pathErrors = new ArrayList<>();
        double bestWhitted = Double.POSITIVE_INFINITY;
        for (Measurement m : physics) {
            if (m.config().isPath()) {
                pathErrors.add(m.relMse());
            } else if (!m.config().isPhysical()) {
                bestWhitted = Math.min(bestWhitted, m.relMse());
            }
        }
        assertEquals(4, pathErrors.size());
        for (int i = 1; i < pathErrors.size(); i++) {
            assertTrue(pathErrors.get(i) < pathErrors.get(i - 1) / 2, pathErrors.toString());
        }
        assertTrue(bestWhitted > 10 * pathErrors.get(3), bestWhitted + " against " + pathErrors);
        AccuracyReport.Verdict verdict = AccuracyReport.verdict("bounce-box", physics);
        assertTrue(verdict.pathWinsRelMse().config().isPath());

        StudyOutput.write(dir, results, "meta\n");
        BufferedImage chart = ImageIO.read(dir.resolve("images/accuracy-bounce-box.png").toFile());
        assertEquals(1800, chart.getWidth());
        assertTrue(Files.isRegularFile(dir.resolve("images/accuracy-whitted.png")));
        String doc = Files.readString(dir.resolve("accuracy.md"));
        for (String section : List.of("accuracy-verdict", "accuracy-validation", "accuracy-whitted-tables")) {
            assertTrue(doc.contains("<!-- generated:" + section + " -->"), section);
        }
        String tables = Files.readString(dir.resolve("accuracy-tables.md"));
        assertTrue(tables.contains("<!-- generated:accuracy-tables -->"), tables);
        assertFalse(doc.contains("<!-- generated:accuracy-tables -->"), "the tables have a page of their own");
        doc += tables;
        for (StudyConfig config : plan.configs()) {
            if (StudyConfigs.methods().contains(config)) {
                assertTrue(doc.contains("| " + config.methodLabel() + " |") || doc.contains("**" + config.methodLabel()),
                        config.methodLabel());
            }
        }
        assertTrue(doc.contains("| bounce-box | the study's reference: path, 100x75, 256 samples, depth 64 |"), doc);
    }
}
