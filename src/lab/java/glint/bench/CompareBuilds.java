package glint.bench;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Compares the render CPU a frame of two or more builds of Glint in one JVM, taking turns: each
 * build's jar gets a class loader of its own, and its {@code glint.app.Main.run} renders a short
 * {@code --bench} of the scene, A then B, then B then A, and so on (with three builds A B C, then
 * C B A). Each run counts its least render CPU over the frames after the first; each round gives a
 * ratio of every build to A, and the median ratio with its quartiles is the result. A machine whose
 * speed drifts from minute to minute drifts under every build alike, since they take turns every
 * second or so.
 *
 * <p>Usage, from the repository root: {@code java -cp target/benchmarks.jar glint.bench.CompareBuilds
 * A.jar B.jar [C.jar ...] [--pairs N] [--threads T] [--depth D] [--size WxH] [--config FILE] SCENE...}
 * (default 12 rounds after 3 for warming up, 2 threads, depth 5, 800x600, 1 sample a pixel,
 * ./config.properties). Every build must read the scene: older builds do not know every key of
 * newer ones.
 */
public final class CompareBuilds {

    private static final Pattern FRAME_CPU = Pattern.compile("^frame \\d+: [0-9.]+ ms, render cpu ([0-9.]+) ms$",
            Pattern.MULTILINE);
    private static final int WARM_UP_PAIRS = 3;
    private static final int FRAMES_A_RUN = 4;

    private CompareBuilds() {
    }

    /** One scene's result: the median render CPU a frame of each build and the ratio's median and quartiles. */
    record Result(String scene, double medianA, double medianB, double ratio, double ratioQ1, double ratioQ3) {

        String line() {
            return String.format(Locale.ROOT, "%s: A %.1f ms, B %.1f ms; B/A %.3f (quartiles %.3f-%.3f)", scene,
                    medianA, medianB, ratio, ratioQ1, ratioQ3);
        }
    }

    public static void main(String[] args) throws Exception {
        try {
            run(args);
        } catch (IllegalArgumentException | IllegalStateException | IndexOutOfBoundsException e) {
            System.err.println("CompareBuilds: " + e.getMessage());
            System.exit(2);
        }
    }

    private static void run(String[] args) throws Exception {
        List<String> rest = new ArrayList<>(Arrays.asList(args));
        int pairs = Integer.parseInt(option(rest, "--pairs", "12"));
        String threads = option(rest, "--threads", "2");
        String depth = option(rest, "--depth", "5");
        String[] size = option(rest, "--size", "800x600").split("x");
        String config = option(rest, "--config", null);
        int jars = 0;
        while (jars < rest.size() && rest.get(jars).endsWith(".jar")) {
            jars++;
        }
        if (jars < 2 || rest.size() == jars) {
            System.err.println("usage: CompareBuilds A.jar B.jar [C.jar ...] [--pairs N] [--threads T] [--depth D]"
                    + " [--size WxH] [--config FILE] SCENE...");
            System.exit(2);
        }
        List<Method> builds = new ArrayList<>();
        StringBuilder names = new StringBuilder();
        for (int i = 0; i < jars; i++) {
            builds.add(mainOf(Path.of(rest.get(i))));
            names.append(i == 0 ? "" : ", ").append((char) ('A' + i)).append(" = ").append(rest.get(i));
        }
        System.out.println(names + "; render CPU a frame, " + pairs + " rounds, " + threads + " threads");
        for (String scene : rest.subList(jars, rest.size())) {
            List<String> bench = new ArrayList<>(List.of("--scene", scene, "--width", size[0], "--height", size[1],
                    "--spp", "1", "--depth", depth, "--threads", threads, "--bench", String.valueOf(FRAMES_A_RUN)));
            if (config != null) {
                bench.addAll(List.of("--config", config));
            }
            for (Result result : compareAll(scene, builds, bench.toArray(new String[0]), pairs)) {
                System.out.println(result.line());
            }
        }
    }

    /** Runs {@code pairs} pairs (after the warm-up ones), alternating which build goes first. */
    static Result compare(String scene, Method a, Method b, String[] bench, int pairs) throws Exception {
        return compareAll(scene, List.of(a, b), bench, pairs).get(0);
    }

    /**
     * Runs {@code rounds} rounds (after the warm-up ones) of every build in turn, forwards in even
     * rounds and backwards in odd ones; returns each build after the first against the first.
     */
    static List<Result> compareAll(String scene, List<Method> builds, String[] bench, int rounds) throws Exception {
        int n = builds.size();
        double[][] cpu = new double[n][rounds];
        for (int round = -WARM_UP_PAIRS; round < rounds; round++) {
            for (int turn = 0; turn < n; turn++) {
                int build = (round & 1) == 0 ? turn : n - 1 - turn;
                double least = leastCpu(builds.get(build), bench);
                if (round >= 0) {
                    cpu[build][round] = least;
                }
            }
        }
        List<Result> results = new ArrayList<>();
        for (int build = 1; build < n; build++) {
            double[] ratios = new double[rounds];
            for (int round = 0; round < rounds; round++) {
                ratios[round] = cpu[build][round] / cpu[0][round];
            }
            String label = n == 2 ? scene : scene + " " + (char) ('A' + build);
            results.add(new Result(label, quantile(cpu[0], 0.5), quantile(cpu[build], 0.5), quantile(ratios, 0.5),
                    quantile(ratios, 0.25), quantile(ratios, 0.75)));
        }
        return results;
    }

    /** The least render CPU of a {@code --bench} run's frames after the first. */
    static double leastCpu(Method main, String[] bench) throws Exception {
        return leastAfterFirst(run(main, bench));
    }

    /** Runs {@code glint.app.Main.run} of a build with these arguments; returns its standard output. */
    static String run(Method main, String[] args) throws Exception {
        StringWriter out = new StringWriter(), err = new StringWriter();
        int status;
        try {
            status = (Integer) main.invoke(null, args, new PrintWriter(out, true), new PrintWriter(err, true));
        } catch (InvocationTargetException e) {
            throw new IllegalStateException("the build failed: " + e.getCause(), e.getCause());
        }
        if (status != 0) {
            throw new IllegalStateException("the build exited with " + status + ": " + err.toString().strip());
        }
        return out.toString();
    }

    /** The least render CPU of the frame lines of {@code --bench} output, the first frame left out. */
    static double leastAfterFirst(String benchOutput) {
        Matcher m = FRAME_CPU.matcher(benchOutput);
        double least = Double.POSITIVE_INFINITY;
        for (int frame = 0; m.find(); frame++) {
            if (frame > 0) {
                least = Math.min(least, Double.parseDouble(m.group(1)));
            }
        }
        if (least == Double.POSITIVE_INFINITY) {
            throw new IllegalStateException("no render cpu after the first frame in: " + benchOutput.strip());
        }
        return least;
    }

    /** The q-quantile of the values, interpolated between neighbours of the sorted copy. */
    static double quantile(double[] values, double q) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        double at = q * (sorted.length - 1);
        int below = (int) Math.floor(at);
        int above = Math.min(below + 1, sorted.length - 1);
        return sorted[below] + (at - below) * (sorted[above] - sorted[below]);
    }

    /**
     * {@code glint.app.Main.run} of the build in a jar (or a classes folder), in a class loader of its
     * own; {@code libraries} are what a classes folder needs beside it (a product jar holds them).
     */
    static Method mainOf(Path build, URL... libraries) throws Exception {
        if (!Files.exists(build)) {
            throw new IllegalArgumentException(build + ": no such jar");
        }
        URL[] path = new URL[libraries.length + 1];
        path[0] = build.toUri().toURL();
        System.arraycopy(libraries, 0, path, 1, libraries.length);
        URLClassLoader loader = new URLClassLoader(path, ClassLoader.getPlatformClassLoader());
        return loader.loadClass("glint.app.Main").getMethod("run", String[].class, PrintWriter.class,
                PrintWriter.class);
    }

    /** Removes option {@code name} and its value from {@code args}; returns the value, or {@code fallback}. */
    static String option(List<String> args, String name, String fallback) {
        int i = args.indexOf(name);
        if (i < 0) {
            return fallback;
        }
        String value = args.get(i + 1);
        args.subList(i, i + 2).clear();
        return value;
    }
}
