package glint.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import glint.bench.BenchReport.Result;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** JMH's JSON read back, the results table, and the page and charts the report writes. */
class BenchReportTest {

    private static final String JSON = """
            [
              {"benchmark": "glint.bench.FrameBenchmark.renderFrame", "mode": "avgt",
               "params": {"material": "glass", "spheres": "5", "threads": "2"},
               "primaryMetric": {"score": 30.5, "scoreError": 2.25,
                 "scorePercentiles": {"0.0": 29.0, "50.0": 30.0, "90.0": 32.5, "100.0": 32.5},
                 "scoreUnit": "ms/op", "rawData": [[32.5, 30.0, 29.0]]}},
              {"benchmark": "glint.bench.FrameBenchmark.renderFrame", "mode": "avgt",
               "params": {"material": "glass", "spheres": "1", "threads": "2"},
               "primaryMetric": {"score": 12.0, "scoreError": 1.0,
                 "scorePercentiles": {"0.0": 11.0, "50.0": 12.5, "100.0": 12.5},
                 "scoreUnit": "ms/op", "rawData": [[11.0, 12.5, 12.5]]}},
              {"benchmark": "glint.bench.SceneBenchmark.raysPerSecond", "mode": "thrpt",
               "params": {"scene": "default"},
               "primaryMetric": {"score": 1500.0, "scoreError": 100.0,
                 "scorePercentiles": {"0.0": 1400.0, "50.0": 1490.0, "100.0": 1620.0},
                 "scoreUnit": "ops/s", "rawData": [[1400.0, 1490.0, 1620.0]]}}
            ]
            """;

    @Test
    void readsTheMeanItsErrorAndTheMedianAndRangeOfTheIterations(@TempDir Path dir) throws Exception {
        Path json = Files.writeString(dir.resolve("jmh.json"), JSON);
        List<Result> results = BenchReport.read(json);
        assertEquals(3, results.size());
        Result first = results.get(0);
        assertEquals("glint.bench.FrameBenchmark.renderFrame", first.benchmark());
        assertEquals(Map.of("material", "glass", "spheres", "5", "threads", "2"), first.params());
        assertEquals(30.5, first.score());
        assertEquals(2.25, first.error());
        assertEquals(30.0, first.median());
        assertEquals(29.0, first.min());
        assertEquals(32.5, first.max());
        assertEquals("ms/op", first.unit());
    }

    @Test
    void theRenderThreadsAreTheBenchmarksParameterUnderItsNameNowOrItsNameBefore(@TempDir Path dir) throws Exception {
        String renamed = JSON.replace("\"threads\"", "\"renderThreads\"");
        List<Result> results = BenchReport.read(Files.writeString(dir.resolve("jmh.json"), renamed));
        assertEquals("2", results.get(0).renderThreads());
        assertEquals(Map.of("material", "glass", "spheres", "5", "renderThreads", "2"), results.get(0).params());
        List<Result> before = BenchReport.read(Files.writeString(dir.resolve("before.json"), JSON));
        assertEquals("2", before.get(1).renderThreads());
        assertEquals("", before.get(2).renderThreads()); // a benchmark without the parameter
    }

    @Test
    void theTableGivesMediansRangesMeansAndTheFrameRateOfFrameTimesOnly(@TempDir Path dir) throws Exception {
        List<Result> results = BenchReport.read(Files.writeString(dir.resolve("jmh.json"), JSON));
        assertEquals("""
                Generated from `jmh.json` by `java -cp target/benchmarks.jar glint.bench.BenchReport jmh.json`.

                | benchmark | parameters | median | range | mean ± error (99.9%) | unit | frames per second (median) |
                |---|---|---:|---:|---:|---|---:|
                | FrameBenchmark.renderFrame | material=glass, spheres=5, threads=2 | 30.00 | 29.00-32.50 | 30.50 ± 2.25 | ms/op | 33.3 |
                | FrameBenchmark.renderFrame | material=glass, spheres=1, threads=2 | 12.50 | 11.00-12.50 | 12.00 ± 1.00 | ms/op | 80.0 |
                | SceneBenchmark.raysPerSecond | scene=default | 1490.00 | 1400.00-1620.00 | 1500.00 ± 100.00 | ops/s |  |
                """, BenchReport.table(results, "jmh.json"));
    }

    @Test
    void rewritesOnlyTheResultsBetweenTheMarkersAndDrawsTheChartsOfTheMaterialsMeasured(@TempDir Path dir)
            throws Exception {
        Path json = Files.writeString(dir.resolve("jmh.json"), JSON);
        Path docs = Files.createDirectories(dir.resolve("docs"));
        Path page = Files.writeString(docs.resolve("benchmarks.md"),
                "# Benchmarks\n\nwritten by hand\n\n" + BenchReport.START + "\nold table\n" + BenchReport.END + "\n\nafter\n");
        BenchReport.main(new String[] {json.toString(), docs.toString()});
        String table = BenchReport.table(BenchReport.read(json), json.toString());
        String expected = "# Benchmarks\n\nwritten by hand\n\n" + BenchReport.START + "\n" + table + BenchReport.END
                + "\n\nafter\n";
        assertEquals(expected, Files.readString(page));
        BenchReport.main(new String[] {json.toString(), docs.toString()});
        assertEquals(expected, Files.readString(page), "a second run leaves the page as the first wrote it");

        BufferedImage glass = ImageIO.read(docs.resolve("images/bench-glass.png").toFile());
        assertEquals(800, glass.getWidth());
        assertEquals(500, glass.getHeight());
        assertFalse(Files.exists(docs.resolve("images/bench-matte.png")), "no matte results, no matte chart");
        assertFalse(Files.exists(docs.resolve("images/bench-threads.png")), "one thread count: no chart along them");
    }

    /** One benchmark of the documented minute: a thread count, a sphere count and a material. */
    private static String frame(int threads, int spheres, String material, double median) {
        return String.format(java.util.Locale.ROOT, """
                  {"benchmark": "glint.bench.FrameBenchmark.renderFrame", "mode": "avgt",
                   "params": {"material": "%s", "renderThreads": "%d", "spheres": "%d"},
                   "primaryMetric": {"score": %.1f, "scoreError": 9.0,
                     "scorePercentiles": {"0.0": %.1f, "50.0": %.1f, "100.0": %.1f},
                     "scoreUnit": "ms/op", "rawData": [[1.0]]}}""", material, threads, spheres, median, median - 2,
                median, median + 5);
    }

    @Test
    void aSliceOfThreadCountsIsChartedAlongTheThreadsNotAlongOneSphereCount(@TempDir Path dir) throws Exception {
        StringBuilder json = new StringBuilder("[");
        for (int threads : new int[] {1, 2, 4}) {
            for (String material : new String[] {"matte", "glass"}) {
                json.append(json.length() > 1 ? ",\n" : "\n").append(frame(threads, 25, material, 100.0 / threads));
            }
        }
        Path file = Files.writeString(dir.resolve("jmh.json"), json.append("\n]\n"));
        Path docs = Files.createDirectories(dir.resolve("out"));
        BenchReport.main(new String[] {file.toString(), docs.toString()});
        BufferedImage threads = ImageIO.read(docs.resolve("images/bench-threads.png").toFile());
        assertEquals(800, threads.getWidth());
        assertFalse(Files.exists(docs.resolve("images/bench-glass.png")), "one sphere count: no chart along them");
        assertFalse(Files.exists(docs.resolve("images/bench-matte.png")));
    }

    @Test
    void writesUnderTargetUnlessToldToUpdateTheDocsOrGivenAFolder() {
        assertEquals(Path.of("target/bench-report"), BenchReport.output("target/jmh.json"));
        assertEquals(Path.of("docs"), BenchReport.output("target/jmh.json", "--docs"));
        assertEquals(Path.of("out"), BenchReport.output("target/jmh.json", "out"));
    }
}
