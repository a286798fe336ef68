package glint.bench;

import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The path integrator's speed against Whitted's on the same scenes, in one JVM, taking turns as
 * {@link CompareBuilds} does (Whitted then path, then path then Whitted, ...): per scene the median
 * render CPU a frame of each, that CPU per sample a pixel, rays per second of render CPU, and the
 * median ratio path / Whitted with its quartiles. Both render the same frames with the same
 * settings; only {@code --integrator} differs.
 *
 * <p>Usage, from the repository root: {@code java -cp target/benchmarks.jar glint.bench.CompareIntegrators
 * [--pairs N] [--threads T] [--depth D] [--size WxH] [--spp S] [--config FILE] SCENE...} (default 12
 * rounds after 3 for warming up, 2 threads, depth 5, 800x600, 1 sample a pixel, ./config.properties).
 */
public final class CompareIntegrators {

    private static final Pattern SUMMARY = Pattern.compile("^bench: frames=(\\d+) median_ms=([0-9.]+) .*rays_per_s=([0-9.]+)$",
            Pattern.MULTILINE);
    private static final String[] INTEGRATORS = {"whitted", "path"};

    private CompareIntegrators() {
    }

    /** One integrator's run: its least render CPU a frame after the first, and the rays a frame. */
    record Run(double cpuMillis, double raysPerFrame) {
    }

    public static void main(String[] args) throws Exception {
        try {
            run(args);
        } catch (IllegalArgumentException | IllegalStateException | IndexOutOfBoundsException e) {
            System.err.println("CompareIntegrators: " + e.getMessage());
            System.exit(2);
        }
    }

    private static void run(String[] args) throws Exception {
        List<String> rest = new ArrayList<>(Arrays.asList(args));
        int rounds = Integer.parseInt(CompareBuilds.option(rest, "--pairs", "12"));
        String threads = CompareBuilds.option(rest, "--threads", "2");
        String depth = CompareBuilds.option(rest, "--depth", "5");
        String[] size = CompareBuilds.option(rest, "--size", "800x600").split("x");
        String spp = CompareBuilds.option(rest, "--spp", "1");
        String config = CompareBuilds.option(rest, "--config", null);
        if (rest.isEmpty()) {
            System.err.println("usage: CompareIntegrators [--pairs N] [--threads T] [--depth D] [--size WxH] [--spp S]"
                    + " [--config FILE] SCENE...");
            System.exit(2);
        }
        Method main = Class.forName("glint.app.Main").getMethod("run", String[].class, java.io.PrintWriter.class,
                java.io.PrintWriter.class);
        double pixelSamples = Double.parseDouble(size[0]) * Double.parseDouble(size[1]) * Integer.parseInt(spp);
        System.out.printf(Locale.ROOT, "path against whitted: render CPU a frame, %d rounds, %s threads, depth %s, %sx%s, "
                + "%s spp%n", rounds, threads, depth, size[0], size[1], spp);
        for (String scene : rest) {
            List<String> bench = new ArrayList<>(List.of("--scene", scene, "--width", size[0], "--height", size[1],
                    "--spp", spp, "--depth", depth, "--threads", threads, "--bench", "4"));
            if (config != null) {
                bench.addAll(List.of("--config", config));
            }
            Run[][] runs = new Run[2][rounds];
            for (int round = -3; round < rounds; round++) {
                for (int turn = 0; turn < 2; turn++) {
                    int which = (round & 1) == 0 ? turn : 1 - turn;
                    List<String> a = new ArrayList<>(bench);
                    a.addAll(List.of("--integrator", INTEGRATORS[which]));
                    Run r = parse(CompareBuilds.run(main, a.toArray(new String[0])));
                    if (round >= 0) {
                        runs[which][round] = r;
                    }
                }
            }
            System.out.println(line(scene, runs, pixelSamples));
        }
    }

    static Run parse(String benchOutput) {
        Matcher m = SUMMARY.matcher(benchOutput);
        if (!m.find()) {
            throw new IllegalStateException("no bench summary in: " + benchOutput.strip());
        }
        double raysPerFrame = Double.parseDouble(m.group(3)) * Double.parseDouble(m.group(2)) / 1000;
        return new Run(CompareBuilds.leastAfterFirst(benchOutput), raysPerFrame);
    }

    /** A scene's line: each integrator's median CPU a frame, per sample a pixel and rays a CPU second; the ratio. */
    static String line(String scene, Run[][] runs, double pixelSamples) {
        int rounds = runs[0].length;
        StringBuilder b = new StringBuilder(scene).append(':');
        double[][] cpu = new double[2][rounds], raysPerSecond = new double[2][rounds];
        double[] ratio = new double[rounds];
        for (int round = 0; round < rounds; round++) {
            for (int i = 0; i < 2; i++) {
                cpu[i][round] = runs[i][round].cpuMillis();
                raysPerSecond[i][round] = runs[i][round].raysPerFrame() / (runs[i][round].cpuMillis() / 1000);
            }
            ratio[round] = cpu[1][round] / cpu[0][round];
        }
        for (int i = 0; i < 2; i++) {
            double median = CompareBuilds.quantile(cpu[i], 0.5);
            b.append(String.format(Locale.ROOT, " %s %.1f ms (%.0f ns a sample, %.2fM rays a CPU second, %.1f rays a"
                            + " sample);", INTEGRATORS[i], median, median * 1e6 / pixelSamples,
                    CompareBuilds.quantile(raysPerSecond[i], 0.5) / 1e6, runs[i][0].raysPerFrame() / pixelSamples));
        }
        return b.append(String.format(Locale.ROOT, " path/whitted %.3f (quartiles %.3f-%.3f)",
                CompareBuilds.quantile(ratio, 0.5), CompareBuilds.quantile(ratio, 0.25),
                CompareBuilds.quantile(ratio, 0.75))).toString();
    }
}
