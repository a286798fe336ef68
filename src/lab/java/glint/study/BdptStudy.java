package glint.study;

import glint.config.Config;
import glint.image.FrameBuffer;
import glint.image.PfmReader;
import glint.render.LightTransport;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Shading;
import glint.render.Tracer;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.knowm.xchart.XYChart;

/**
 * The bidirectional integrator where the path tracer fails, measured (docs/accuracy.md, "Caustics"):
 * <ol>
 * <li>on scenes with caustics (caustic-lamp against the independent reference; scenes/caustics.yaml
 * against bdpt's own image at {@link #REFERENCE_SAMPLES}), error against render CPU for both, and bdpt's
 * relMSE and FLIP over the path tracer's at the same render CPU (the path's interpolated on log axes);
 * <li>the caustic under caustic-lamp's glass ball: its mean radiance against the reference's;
 * <li>relMSE falling with the samples on the default and metals scenes at 100 x 75, each against bdpt's
 * own image at 4096 samples, over 16 x {@link #FALL_FRAMES} frames at 16 samples and {@link #FALL_FRAMES} at 256
 * (no firefly plateau);
 * <li>sky-and-sun, whose reference lacks the caustic of its glass ball under the sun: by how much.
 * </ol>
 * Usage: {@code java -cp target/benchmarks.jar glint.study.BdptStudy [--docs | --caustic | --fall]}; --docs writes the
 * chart to docs/images, --caustic runs the second part alone, --fall the third. Depth 64, 2 render threads, cook-torrance; render CPU is the render threads' CPU time.
 */
public final class BdptStudy {

    static final int DEPTH = 64;
    /** Samples of a converged bdpt image, where no independent one exists. */
    static final int REFERENCE_SAMPLES = 4096;
    private static final Path REFERENCES = Path.of("src/test/resources/reference-pt");

    private BdptStudy() {
    }

    /** A way to render: an integrator, and for bdpt whether it merges as well as joins. */
    enum Method {
        PATH("path", LightTransport.PATH, false), BDPT("bdpt", LightTransport.BDPT, true),
        JOINS_ONLY("bdpt, joins only", LightTransport.BDPT, false);

        final String label;
        final LightTransport transport;
        final boolean merging;

        Method(String label, LightTransport transport, boolean merging) {
            this.label = label;
            this.transport = transport;
            this.merging = merging;
        }
    }

    /** One render: its method, samples, render CPU in ms and errors against the reference. */
    record Point(Method method, int samples, double cpuMillis, double relMse, double flip) {
    }

    public static void main(String[] args) throws Exception {
        boolean docs = List.of(args).contains("--docs");
        if (List.of(args).contains("--caustic")) { // that check alone
            System.out.print(causticUnderTheBall(PfmReader.read(REFERENCES.resolve("caustic-lamp.pfm"))));
            return;
        }
        Locale.setDefault(Locale.ROOT);
        if (List.of(args).contains("--fall")) { // that check alone
            System.out.print(fallsWithSamples("default") + fallsWithSamples("metals"));
            return;
        }
        List<XYChart> charts = new ArrayList<>();
        StringBuilder out = new StringBuilder();
        out.append("| scene | method | samples | render CPU | relMSE / path's at that CPU | FLIP / path's |\n")
                .append("|---|---|--:|--:|--:|--:|\n");
        FrameBuffer causticLamp = PfmReader.read(REFERENCES.resolve("caustic-lamp.pfm"));
        Scene lamp = load(REFERENCES.resolve("caustic-lamp.yaml"));
        for (Method m : Method.values()) { // compiled before any render is timed, so no method pays for it
            render(lamp, m, 100, 75, 16);
        }
        equalCpu("caustic-lamp", lamp, causticLamp, out, charts);
        Scene caustics = load(Path.of("scenes/caustics.yaml"));
        FrameBuffer causticsReference = render(caustics, Method.JOINS_ONLY, 200, 150, REFERENCE_SAMPLES).frame;
        equalCpu("caustics", caustics, causticsReference, out, charts);
        out.append('\n').append(causticUnderTheBall(causticLamp)).append('\n');
        out.append(fallsWithSamples("default")).append(fallsWithSamples("metals"));
        out.append('\n').append(skyAndSun());
        System.out.print(out);
        Path images = docs ? Path.of("docs/images") : Path.of("target/study-bdpt");
        Files.createDirectories(images);
        Charts.save(charts, 1, charts.size(), images.resolve("accuracy-caustics.png"));
        System.out.println("chart: " + images.resolve("accuracy-caustics.png"));
    }

    /** Path at 16 to 1024 samples and bdpt at 4 to 256 against {@code reference}: a table row per bdpt point and a chart. */
    static void equalCpu(String name, Scene scene, FrameBuffer reference, StringBuilder out, List<XYChart> charts) {
        int w = reference.width(), h = reference.height();
        List<Point> path = new ArrayList<>(), bdpt = new ArrayList<>(), joins = new ArrayList<>();
        for (int samples : new int[] {16, 64, 256, 1024}) {
            path.add(point(scene, Method.PATH, samples, reference));
        }
        for (int samples : new int[] {4, 16, 64, 256}) {
            bdpt.add(point(scene, Method.BDPT, samples, reference));
            joins.add(point(scene, Method.JOINS_ONLY, samples, reference));
        }
        for (List<Point> points : List.of(bdpt, joins)) {
            for (Point b : points) {
                out.append(String.format("| %s | %s | %d | %.0f ms | %.2f | %.2f |%n", name, b.method().label,
                        b.samples(), b.cpuMillis(), b.relMse() / atCpu(path, b.cpuMillis(), true),
                        b.flip() / atCpu(path, b.cpuMillis(), false)));
            }
        }
        for (List<Point> points : List.of(path, bdpt, joins)) {
            for (Point p : points) {
                System.err.printf("%s %s s%d: %.0f ms, relMSE %.3e, FLIP %.4f%n", name, p.method().label,
                        p.samples(), p.cpuMillis(), p.relMse(), p.flip());
            }
        }
        XYChart chart = Charts.chart(name + ": relative MSE against render CPU", "render CPU (ms)", "relative MSE",
                true, true, 600);
        Charts.line(chart, "path s16-1024", cpu(path), errors(path, true), 0, false);
        Charts.line(chart, "bdpt s4-256", cpu(bdpt), errors(bdpt, true), 4, false);
        Charts.line(chart, "bdpt, joins only, s4-256", cpu(joins), errors(joins, true), 1, true);
        charts.add(chart);
        XYChart flip = Charts.chart(name + ": FLIP against render CPU", "render CPU (ms)", "mean FLIP", true, true, 600);
        Charts.line(flip, "path s16-1024", cpu(path), errors(path, false), 0, false);
        Charts.line(flip, "bdpt s4-256", cpu(bdpt), errors(bdpt, false), 4, false);
        Charts.line(flip, "bdpt, joins only, s4-256", cpu(joins), errors(joins, false), 1, true);
        charts.add(flip);
    }

    /** The path tracer's error at render CPU {@code cpu}: interpolated between its points on log axes, extrapolated past them. */
    static double atCpu(List<Point> path, double cpu, boolean relMse) {
        int i = 1;
        while (i < path.size() - 1 && path.get(i).cpuMillis() < cpu) {
            i++;
        }
        Point a = path.get(i - 1), b = path.get(i);
        double ea = relMse ? a.relMse() : a.flip(), eb = relMse ? b.relMse() : b.flip();
        double t = Math.log(cpu / a.cpuMillis()) / Math.log(b.cpuMillis() / a.cpuMillis());
        return Math.exp(Math.log(ea) + t * (Math.log(eb) - Math.log(ea)));
    }

    /** The mean radiance of the caustic under caustic-lamp's glass ball (its brightest floor pixels) in bdpt, path and the reference. */
    static String causticUnderTheBall(FrameBuffer reference) {
        Scene scene = load(REFERENCES.resolve("caustic-lamp.yaml"));
        FrameBuffer bdpt = render(scene, Method.BDPT, 200, 150, 1024).frame;
        FrameBuffer path = render(scene, Method.PATH, 200, 150, 1024).frame;
        // the caustic: pixels under the ball (rows 80 on, columns 50 to 149) whose reference is above 4x the
        // median of the floor (rows 110 on)
        List<Integer> spot = new ArrayList<>();
        double[] floor = new double[reference.width() * (reference.height() - 110)];
        int n = 0;
        for (int y = 110; y < reference.height(); y++) {
            for (int x = 0; x < reference.width(); x++) {
                floor[n++] = luminance(reference, x, y);
            }
        }
        java.util.Arrays.sort(floor);
        double median = floor[floor.length / 2];
        for (int y = 80; y < reference.height(); y++) {
            for (int x = 50; x < 150; x++) {
                if (luminance(reference, x, y) > 4 * median) {
                    spot.add(y * reference.width() + x);
                }
            }
        }
        return String.format("caustic under caustic-lamp's glass ball (%d pixels): mean radiance reference %.3f, "
                        + "bdpt 1024 %.3f (%+.1f %%), path 1024 %.3f (%+.1f %%)%n", spot.size(), mean(reference, spot),
                mean(bdpt, spot), 100 * (mean(bdpt, spot) / mean(reference, spot) - 1), mean(path, spot),
                100 * (mean(path, spot) / mean(reference, spot) - 1));
    }

    /**
     * Frames (seeds) at 256 samples the fall with samples is averaged over, and 16 times as many at 16, so
     * that both budgets draw the same samples in all and meet a pixel's rarest paths as often: one frame's
     * relMSE is ruled by them (on metals, 16 frames at 16 samples and 16 at 256 gave a mean fall of 7.6;
     * 256 at 16 and 16 at 256, 188, one frame at 16 holding a sample 30 000 times its pixel's value).
     */
    static final int FALL_FRAMES = 16;

    /**
     * relMSE at 16 and 256 samples at 100 x 75, over 16 x {@link #FALL_FRAMES} and {@link #FALL_FRAMES} frames
     * (seeds): bdpt's and the path's against bdpt's image at 4096, bdpt's with joins only against its own
     * at 4096 (what merging adds); how far the mean and the median fall.
     */
    static String fallsWithSamples(String name) {
        Scene scene = load(Path.of("scenes", name + ".yaml"));
        FrameBuffer bdpt = render(scene, Method.BDPT, 100, 75, 4096, 0).frame;
        FrameBuffer joins = render(scene, Method.JOINS_ONLY, 100, 75, 4096, 0).frame;
        StringBuilder out = new StringBuilder();
        for (Method m : List.of(Method.BDPT, Method.JOINS_ONLY, Method.PATH)) {
            FrameBuffer own = m == Method.JOINS_ONLY ? joins : bdpt;
            double[] at16 = new double[16 * FALL_FRAMES], at256 = new double[FALL_FRAMES];
            for (int f = 0; f < at16.length; f++) {
                at16[f] = RelativeMse.of(render(scene, m, 100, 75, 16, f + 1).frame, own);
            }
            for (int f = 0; f < at256.length; f++) {
                at256[f] = RelativeMse.of(render(scene, m, 100, 75, 256, f + 1).frame, own);
            }
            out.append(String.format("%s at 100 x 75 against %s at 4096, %s, %d frames at 16 samples, %d at 256: "
                            + "relMSE at 16 mean %.2e, median %.2e, largest %.2e; at 256 %s; mean falls %.1fx, median %.1fx%n",
                    name, m == Method.JOINS_ONLY ? m.label : "bdpt", m.label, at16.length, at256.length, mean(at16),
                    median(at16), max(at16), list(at256), mean(at16) / mean(at256), median(at16) / median(at256)));
        }
        return out.toString();
    }

    private static String list(double[] values) {
        StringBuilder s = new StringBuilder();
        for (double v : values) {
            s.append(s.length() == 0 ? "" : ", ").append(String.format("%.2e", v));
        }
        return s.toString();
    }

    private static double max(double[] values) {
        return java.util.Arrays.stream(values).max().orElse(Double.NaN);
    }

    private static double mean(double[] values) {
        return java.util.Arrays.stream(values).average().orElse(Double.NaN);
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        java.util.Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }

    /** sky-and-sun: bdpt at 256 against the reference, which lacks the sun's caustic under the glass ball. */
    static String skyAndSun() throws IOException {
        FrameBuffer reference = PfmReader.read(REFERENCES.resolve("sky-and-sun.pfm"));
        Scene scene = load(REFERENCES.resolve("sky-and-sun.yaml"));
        FrameBuffer bdpt = render(scene, Method.BDPT, reference.width(), reference.height(), 256).frame;
        FrameBuffer path = render(scene, Method.PATH, reference.width(), reference.height(), 256).frame;
        double bdptMean = mean(bdpt, null), pathMean = mean(path, null), refMean = mean(reference, null);
        return String.format("sky-and-sun at 256 samples: relMSE bdpt %.3e, path %.3e; mean radiance bdpt %.4f, path "
                        + "%.4f, reference %.4f (bdpt %+.2f %%: the caustic)%n", RelativeMse.of(bdpt, reference),
                RelativeMse.of(path, reference), bdptMean, pathMean, refMean, 100 * (bdptMean / refMean - 1));
    }

    private static Point point(Scene scene, Method method, int samples, FrameBuffer reference) {
        Rendered r = render(scene, method, reference.width(), reference.height(), samples);
        return new Point(method, samples, r.cpuMillis, RelativeMse.of(r.frame, reference), Flip.of(r.frame, reference));
    }

    private record Rendered(FrameBuffer frame, double cpuMillis) {
    }

    static Rendered render(Scene scene, Method method, int w, int h, int samples) {
        return render(scene, method, w, h, samples, 0);
    }

    /** Frame {@code frameIndex} (its seed) of the scene by the method, and its render CPU. */
    static Rendered render(Scene scene, Method method, int w, int h, int samples, int frameIndex) {
        Config d = Config.defaults();
        RenderSettings settings = new RenderSettings(Shading.COOK_TORRANCE, DEPTH, d.minWeight(), d.epsilon())
                .withTransport(method.transport).withMerging(method.merging);
        FrameBuffer frame = new FrameBuffer(w, h);
        try (Tracer tracer = new Tracer(2)) {
            RenderScene compiled = RenderScene.compile(scene, settings);
            long before = tracer.renderCpuNanos();
            tracer.render(compiled, frame, samples, frameIndex, d.screenDivider());
            return new Rendered(frame, (tracer.renderCpuNanos() - before) / 1e6);
        }
    }

    private static Scene load(Path file) {
        try {
            return SceneLoader.load(file);
        } catch (Exception e) {
            throw new IllegalStateException("cannot load " + file + ": " + e.getMessage(), e);
        }
    }

    private static double luminance(FrameBuffer f, int x, int y) {
        return 0.2126 * f.get(x, y, 0) + 0.7152 * f.get(x, y, 1) + 0.0722 * f.get(x, y, 2);
    }

    /** The mean luminance over the given pixels (all where null). */
    private static double mean(FrameBuffer f, List<Integer> pixels) {
        double sum = 0;
        int n = 0;
        for (int i = 0; i < f.width() * f.height(); i++) {
            if (pixels == null || pixels.contains(i)) {
                sum += luminance(f, i % f.width(), i / f.width());
                n++;
            }
        }
        return sum / n;
    }

    private static double[] cpu(List<Point> points) {
        return points.stream().mapToDouble(Point::cpuMillis).toArray();
    }

    private static double[] errors(List<Point> points, boolean relMse) {
        return points.stream().mapToDouble(p -> relMse ? p.relMse() : p.flip()).toArray();
    }
}
