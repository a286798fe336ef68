package glint.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * Measures the frame-time targets of docs/records/benchmarks.md as they are stated: rounds of
 * {@code --bench N} (800x600, 1 sample, depth 5), each run in a fresh JVM, for the spec's example scene,
 * 25 glass spheres and 1,000 spheres with 1 and 2 threads, one run after another; then prints the
 * table: the median of the rounds' medians (and of their p95), every round's median, and the
 * speed-up of 2 threads over 1 in each round. On a shared machine the rounds spread widely; the
 * medians over rounds run in turn are what to compare.
 *
 * <p>Usage, from the repository root: {@code java -cp target/benchmarks.jar glint.bench.TargetRounds [rounds] [frames]}
 * (default 6 rounds of 60 frames).
 */
public final class TargetRounds {

    /** A frame-time target: the scene file and the longest median frame it allows with 2 threads. */
    record Target(String name, String scene, double framesPerSecond) {

        double maxMillis() {
            return 1000 / framesPerSecond;
        }
    }

    static final List<Target> TARGETS = List.of(
            new Target("spec example", "scenes/bench/spec-example.yaml", 90),
            new Target("25 glass spheres", "scenes/bench/glass-25.yaml", 25),
            new Target("1,000 spheres", "scenes/bench/field-1000.yaml", 20));

    /** 2 threads must render at least this many times as fast as 1. */
    static final double MIN_SPEEDUP = 1.9;

    /**
     * What one {@code --bench} run printed: the median and p95 of its summary line, and the median of
     * its frames' render CPU time (NaN where the run did not print one).
     */
    record Run(double medianMillis, double p95Millis, double cpuMedianMillis) {
    }

    /** The runs of one target: index [round], with 1 thread and with 2. */
    record Rounds(Target target, List<Run> oneThread, List<Run> twoThreads) {
    }

    private static final Pattern SUMMARY = Pattern.compile("^bench: frames=\\d+ median_ms=([0-9.]+) p95_ms=([0-9.]+) .*");
    private static final Pattern FRAME_CPU = Pattern.compile("^frame \\d+: [0-9.]+ ms, render cpu ([0-9.]+) ms$");

    private TargetRounds() {
    }

    public static void main(String[] args) throws InterruptedException {
        int rounds = positive(args, 0, 6, "rounds");
        int frames = positive(args, 1, 60, "frames");
        for (Target target : TARGETS) {
            if (!Files.isRegularFile(Path.of(target.scene()))) {
                fail(target.scene() + " not found; run this from the repository root");
            }
        }
        List<Rounds> results = new ArrayList<>();
        for (Target target : TARGETS) {
            results.add(new Rounds(target, new ArrayList<>(), new ArrayList<>()));
        }
        try {
            for (int round = 1; round <= rounds; round++) {
                for (Rounds r : results) {
                    for (int threads = 1; threads <= 2; threads++) {
                        Run run = bench(r.target().scene(), threads, frames);
                        (threads == 1 ? r.oneThread() : r.twoThreads()).add(run);
                        System.err.printf(Locale.ROOT, "round %d/%d: %s, %d thread%s: median %.2f ms%n", round,
                                rounds, r.target().name(), threads, threads == 1 ? "" : "s", run.medianMillis());
                    }
                }
            }
        } catch (IOException e) {
            fail(e.getMessage());
        }
        System.out.print(table(results));
    }

    private static int positive(String[] args, int index, int fallback, String name) {
        if (args.length <= index) {
            return fallback;
        }
        try {
            int value = Integer.parseInt(args[index]);
            if (value >= 1) {
                return value;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        fail(name + " must be a whole number of at least 1, got '" + args[index]
                + "'; usage: java -cp target/benchmarks.jar glint.bench.TargetRounds [rounds] [frames]");
        return fallback;
    }

    private static void fail(String message) {
        System.err.println("error: " + message);
        System.exit(2);
    }

    /** Runs {@code glint --bench frames} on the scene in a new JVM (the same java and class path as this one). */
    private static Run bench(String scene, int threads, int frames) throws IOException, InterruptedException {
        String java = ProcessHandle.current().info().command().orElse("java");
        Process process = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), "glint.app.Main",
                "--scene", scene, "--width", "800", "--height", "600", "--spp", "1", "--depth", "5",
                "--threads", Integer.toString(threads), "--bench", Integer.toString(frames))
                .redirectErrorStream(true).start();
        String output = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        int status = process.waitFor();
        if (status != 0 || output.lines().noneMatch(line -> line.startsWith("bench:"))) {
            throw new IOException("the bench run of " + scene + " failed (exit status " + status + "):\n" + output);
        }
        return parse(output);
    }

    /**
     * Reads a {@code --bench} run's output: its summary line, {@code bench: frames=N median_ms=X
     * p95_ms=Y rays_per_s=Z} (the last such line, whatever the JVM printed after it), and the render
     * CPU time of its frame lines.
     */
    static Run parse(String output) {
        List<String> lines = output.lines().collect(Collectors.toList());
        String summary = lines.stream().filter(line -> line.startsWith("bench:")).reduce((a, b) -> b)
                .orElse(lines.isEmpty() ? "" : lines.get(lines.size() - 1));
        Matcher m = SUMMARY.matcher(summary);
        if (!m.matches()) {
            throw new IllegalArgumentException("not a bench summary line: " + summary);
        }
        double[] cpu = lines.stream().map(FRAME_CPU::matcher).filter(Matcher::matches)
                .mapToDouble(frame -> Double.parseDouble(frame.group(1))).toArray();
        return new Run(Double.parseDouble(m.group(1)), Double.parseDouble(m.group(2)),
                cpu.length == 0 ? Double.NaN : median(cpu));
    }

    static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }

    /** The targets table in Markdown: frame times with 2 threads, then the speed-up of 2 threads over 1. */
    static String table(List<Rounds> results) {
        StringBuilder out = new StringBuilder();
        out.append("| target | wanted | median of the rounds' medians (p95) | rounds | met |\n");
        out.append("|---|---|---|---|---|\n");
        for (Rounds r : results) {
            double[] medians = medians(r.twoThreads());
            double median = median(medians);
            double p95 = median(r.twoThreads().stream().mapToDouble(Run::p95Millis).toArray());
            out.append(String.format(Locale.ROOT, "| %s, 2 threads | >= %.0f fps (<= %.1f ms) | %.2f ms (%.0f) = %.0f fps | %s | %s |%n",
                    r.target().name(), r.target().framesPerSecond(), r.target().maxMillis(), median, p95,
                    1000 / median, list(medians, "%.1f"), median <= r.target().maxMillis() ? "yes" : "no"));
        }
        for (Rounds r : results) {
            double[] speedups = speedups(r);
            double median = median(speedups);
            out.append(String.format(Locale.ROOT, "| %s, 2 threads over 1 | >= %.1fx | %.3fx | %s | %s |%n",
                    r.target().name(), MIN_SPEEDUP, median, list(speedups, "%.2f"), median >= MIN_SPEEDUP ? "yes" : "no"));
        }
        out.append(cpuTable(results));
        return out.toString();
    }

    /**
     * The render threads' CPU time a frame (summed over them; median over frames, then over rounds),
     * which leaves out the time they waited for a core, and what it makes of 2 threads over 1 on
     * two free cores: 2 x CPU(1 thread) / CPU(2 threads), were the threads' work split evenly.
     */
    static String cpuTable(List<Rounds> results) {
        StringBuilder out = new StringBuilder();
        boolean measured = results.stream().flatMap(r -> Stream.concat(r.oneThread().stream(),
                r.twoThreads().stream())).noneMatch(run -> Double.isNaN(run.cpuMedianMillis()));
        if (!measured) {
            return ""; // a JVM without thread CPU clocks
        }
        out.append("\n| render CPU a frame | 1 thread | 2 threads | 2 threads over 1 on two free cores |\n");
        out.append("|---|---|---|---|\n");
        for (Rounds r : results) {
            double one = median(cpuMedians(r.oneThread())), two = median(cpuMedians(r.twoThreads()));
            out.append(String.format(Locale.ROOT, "| %s | %.2f ms | %.2f ms | %.3fx |%n",
                    r.target().name(), one, two, 2 * one / two));
        }
        return out.toString();
    }

    private static double[] cpuMedians(List<Run> runs) {
        return runs.stream().mapToDouble(Run::cpuMedianMillis).toArray();
    }

    private static double[] medians(List<Run> runs) {
        return runs.stream().mapToDouble(Run::medianMillis).toArray();
    }

    /** Per round: the 1-thread median over the 2-thread median. */
    private static double[] speedups(Rounds r) {
        double[] one = medians(r.oneThread()), two = medians(r.twoThreads());
        double[] ratio = new double[Math.min(one.length, two.length)];
        for (int i = 0; i < ratio.length; i++) {
            ratio[i] = one[i] / two[i];
        }
        return ratio;
    }

    private static String list(double[] values, String format) {
        return Arrays.stream(values).mapToObj(v -> String.format(Locale.ROOT, format, v)).collect(Collectors.joining(", "));
    }
}
