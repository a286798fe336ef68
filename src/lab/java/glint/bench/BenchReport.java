package glint.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.snakeyaml.engine.v2.api.Load;
import org.snakeyaml.engine.v2.api.LoadSettings;

/**
 * Turns a JMH JSON result file into the charts images/bench-*.png and the results table of
 * benchmarks.md (between its results markers) in an output folder: target/bench-report by default,
 * docs/ itself with {@code --docs}, or the folder given.
 *
 * <p>Usage: {@code java -cp target/benchmarks.jar glint.bench.BenchReport target/jmh.json [--docs | FOLDER]}
 */
public final class BenchReport {

    static final String START = "<!-- results:start -->";
    static final String END = "<!-- results:end -->";

    /**
     * One benchmark result: name, parameters, the mean score and its 99.9% error, and the median,
     * least and greatest of its measured iterations, in {@code unit} (ms per frame for frame times).
     */
    record Result(String benchmark, Map<String, String> params, double score, double error,
                  double median, double min, double max, String unit) {

        String param(String key) {
            return params.getOrDefault(key, "");
        }

        /**
         * The render threads the benchmark ran with: its parameter {@code renderThreads} ({@code threads} in
         * runs before it had that name), not JMH's own "Threads: 1 thread", the threads calling it.
         */
        String renderThreads() {
            return params.containsKey("renderThreads") ? param("renderThreads") : param("threads");
        }
    }

    private BenchReport() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length < 1 || args.length > 2) {
            System.err.println("usage: java -cp target/benchmarks.jar glint.bench.BenchReport JMH_JSON [--docs | FOLDER]");
            System.exit(2);
        }
        Path docs = output(args);
        List<Result> results = read(Path.of(args[0]));
        Files.createDirectories(docs.resolve("images"));
        List<Result> frames = results.stream().filter(r -> r.benchmark().endsWith("FrameBenchmark.renderFrame"))
                .toList();
        for (String material : new String[] {"matte", "glass"}) {
            List<Result> series = frames.stream().filter(r -> r.param("material").equals(material)).toList();
            if (distinct(series, "spheres") > 1) { // a chart along the spheres needs more than one count of them
                writeChart(series, material, docs.resolve("images/bench-" + material + ".png"));
            }
        }
        if (frames.stream().map(Result::renderThreads).distinct().count() > 1) {
            writeThreadsChart(frames, docs.resolve("images/bench-threads.png"));
        }
        Path page = docs.resolve("benchmarks.md");
        String table = table(results, args[0]);
        String text = Files.exists(page) ? Files.readString(page) : "# Benchmarks\n\n" + START + "\n" + END + "\n";
        int a = text.indexOf(START), b = text.indexOf(END);
        if (a < 0 || b < a) {
            text = text + "\n" + START + "\n" + END + "\n";
            a = text.indexOf(START);
            b = text.indexOf(END);
        }
        text = text.substring(0, a + START.length()) + "\n" + table + text.substring(b);
        Files.writeString(page, text, StandardCharsets.UTF_8);
        System.out.println("wrote " + page + " and charts in " + docs.resolve("images"));
    }

    /** The output folder: target/bench-report, docs/ with --docs, or the folder after the JSON file. */
    static Path output(String... args) {
        if (args.length < 2) {
            return Path.of("target/bench-report");
        }
        return Path.of(args[1].equals("--docs") ? "docs" : args[1]);
    }

    @SuppressWarnings("unchecked")
    static List<Result> read(Path json) throws IOException {
        Object root = new Load(LoadSettings.builder().setCodePointLimit(64 * 1024 * 1024).build())
                .loadFromString(Files.readString(json));
        List<Result> results = new ArrayList<>();
        for (Object item : (List<Object>) root) {
            Map<String, Object> entry = (Map<String, Object>) item;
            Map<String, Object> metric = (Map<String, Object>) entry.get("primaryMetric");
            Map<String, String> params = new TreeMap<>();
            Object p = entry.get("params");
            if (p instanceof Map<?, ?> map) {
                map.forEach((k, v) -> params.put(String.valueOf(k), String.valueOf(v)));
            }
            Map<String, Object> percentiles = metric.get("scorePercentiles") instanceof Map<?, ?> m
                    ? (Map<String, Object>) m : Map.of();
            results.add(new Result(String.valueOf(entry.get("benchmark")), params,
                    number(metric.get("score")), number(metric.get("scoreError")),
                    number(percentiles.get("50.0")), number(percentiles.get("0.0")), number(percentiles.get("100.0")),
                    String.valueOf(metric.get("scoreUnit"))));
        }
        return results;
    }

    private static double number(Object value) {
        return value instanceof Number n ? n.doubleValue() : Double.NaN;
    }

    /**
     * The frame time of one material's scenes against their sphere count, a line per thread count:
     * the median of each benchmark's iterations, which a moment's load on a shared machine moves
     * less than the mean.
     */
    private static void writeChart(List<Result> series, String material, Path file) throws IOException {
        XYChart chart = new XYChartBuilder().width(800).height(500)
                .title("Frame time, " + material + " spheres on a floor (800x600, 1 spp, depth 5)")
                .xAxisTitle("spheres").yAxisTitle("ms per frame (median of the iterations)").build();
        chart.getStyler().setLegendVisible(true);
        chart.getStyler().setYAxisMin(0.0);
        TreeSet<Integer> threadCounts = new TreeSet<>();
        series.forEach(r -> threadCounts.add(Integer.parseInt(r.renderThreads())));
        for (int threads : threadCounts) {
            List<Result> line = series.stream().filter(r -> r.renderThreads().equals(String.valueOf(threads)))
                    .sorted((x, y) -> Integer.compare(Integer.parseInt(x.param("spheres")), Integer.parseInt(y.param("spheres"))))
                    .toList();
            double[] x = line.stream().mapToDouble(r -> Double.parseDouble(r.param("spheres"))).toArray();
            double[] y = line.stream().mapToDouble(Result::median).toArray();
            chart.addSeries(threads + (threads == 1 ? " render thread" : " render threads"), x, y).setMarker(SeriesMarkers.CIRCLE);
        }
        BitmapEncoder.saveBitmap(chart, file.toString(), BitmapEncoder.BitmapFormat.PNG);
    }

    private static long distinct(List<Result> results, String param) {
        return results.stream().map(r -> r.param(param)).distinct().count();
    }

    /**
     * Frame time against the render threads, a line per scene (sphere count and material): each point the median
     * of the benchmark's iterations, its error bar reaching the farther of the least and the greatest of them (a
     * bar as wide as the iterations spread; JMH's 99.9 % error of a mean of 3 iterations is many times wider).
     */
    static void writeThreadsChart(List<Result> frames, Path file) throws IOException {
        XYChart chart = new XYChartBuilder().width(800).height(500)
                .title("Frame time against render threads (800x600, 1 spp, depth 5)")
                .xAxisTitle("render threads").yAxisTitle("ms per frame (median; bar: least to greatest iteration)")
                .build();
        chart.getStyler().setLegendVisible(true);
        chart.getStyler().setYAxisMin(0.0);
        chart.getStyler().setXAxisDecimalPattern("#");
        TreeSet<String> scenes = new TreeSet<>((a, b) -> {
            String[] x = a.split(" "), y = b.split(" ");
            int byMaterial = x[1].compareTo(y[1]);
            return byMaterial != 0 ? byMaterial : Integer.compare(Integer.parseInt(x[0]), Integer.parseInt(y[0]));
        });
        frames.forEach(r -> scenes.add(r.param("spheres") + " " + r.param("material")));
        for (String scene : scenes) {
            String[] parts = scene.split(" ");
            List<Result> line = frames.stream()
                    .filter(r -> r.param("spheres").equals(parts[0]) && r.param("material").equals(parts[1]))
                    .sorted((a, b) -> Integer.compare(Integer.parseInt(a.renderThreads()),
                            Integer.parseInt(b.renderThreads())))
                    .toList();
            double[] x = line.stream().mapToDouble(r -> Double.parseDouble(r.renderThreads())).toArray();
            double[] y = line.stream().mapToDouble(Result::median).toArray();
            double[] bars = line.stream().mapToDouble(r -> Math.max(r.max() - r.median(), r.median() - r.min()))
                    .toArray();
            String name = parts[0] + " " + parts[1] + (parts[0].equals("1") ? " sphere" : " spheres");
            chart.addSeries(name, x, y, bars).setMarker(SeriesMarkers.CIRCLE);
        }
        BitmapEncoder.saveBitmap(chart, file.toString(), BitmapEncoder.BitmapFormat.PNG);
    }

    /**
     * The results table in Markdown: per benchmark, the median of its iterations and their range
     * (least to greatest), JMH's mean and 99.9% error, and, for frame times, the frames per second
     * of the median.
     */
    static String table(List<Result> results, String source) {
        StringBuilder md = new StringBuilder();
        md.append(String.format(Locale.ROOT, "Generated from `%s` by `java -cp target/benchmarks.jar glint.bench.BenchReport %s`.%n%n",
                source, source));
        md.append("| benchmark | parameters | median | range | mean ± error (99.9%) | unit | frames per second (median) |\n"
                + "|---|---|---:|---:|---:|---|---:|\n");
        for (Result r : results) {
            String name = r.benchmark().substring(r.benchmark().lastIndexOf('.', r.benchmark().lastIndexOf('.') - 1) + 1);
            boolean frameTime = r.unit().equals("ms/op"); // a frame per operation: its rate means something
            md.append(String.format(Locale.ROOT, "| %s | %s | %.2f | %.2f-%.2f | %.2f ± %.2f | %s | %s |%n", name,
                    r.params().toString().replace("{", "").replace("}", ""), r.median(), r.min(), r.max(), r.score(),
                    r.error(), r.unit(), frameTime ? String.format(Locale.ROOT, "%.1f", 1000 / r.median()) : ""));
        }
        return md.toString();
    }
}
