package glint.study;

import glint.image.FrameBuffer;
import glint.image.ImageWriter;
import glint.image.PfmReader;
import glint.image.ViewTransform;
import glint.render.Convergence;
import glint.render.LightTransport;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Shading;
import glint.render.Tracer;
import glint.scenefile.SceneLoader;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.imageio.ImageIO;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.style.Styler;

/**
 * Adaptive sampling against uniform sampling (docs/accuracy.md, "Adaptive sampling"): on the reference scenes,
 * the error against the independent renderer's image (relMSE and FLIP) against the render CPU, for stills of
 * 16 to 1024 samples a pixel and for adaptive stills of noise thresholds 10 % to 1 % (capped at 1024). Writes
 * the chart, a picture of where the samples went, and the table on standard output.
 *
 * <pre>java -cp target/benchmarks.jar glint.study.AdaptiveStudy [--quick] [OUT_DIR]
 * java -cp target/benchmarks.jar glint.study.AdaptiveStudy --readout</pre>
 * The second prints the window's noise readout on two scenes at 16 to 1024 samples a pixel.
 */
public final class AdaptiveStudy {

    private record Subject(String name, LightTransport transport, int width, int height) {
    }

    private static final List<Subject> SUBJECTS = List.of(
            new Subject("bounce-box", LightTransport.PATH, 200, 150),
            new Subject("sky-and-sun", LightTransport.PATH, 200, 150),
            new Subject("lamp-and-frost", LightTransport.PATH, 200, 150),
            new Subject("caustic-lamp", LightTransport.BDPT, 200, 150));

    private static final int[] UNIFORM = {16, 64, 256, 1024};
    private static final double[] THRESHOLDS = {0.1, 0.05, 0.02, 0.01};
    private static final int CAP = 1024;
    private static final int THREADS = 2;

    private record Point(String method, double cpuMs, double meanSpp, double relMse, double flip) {
    }

    private AdaptiveStudy() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length > 0 && args[0].equals("--readout")) {
            readout();
            return;
        }
        boolean quick = args.length > 0 && args[0].equals("--quick");
        Path out = Path.of(args.length > (quick ? 1 : 0) ? args[quick ? 1 : 0] : quick ? "target/adaptive-quick"
                : "docs/images");
        Files.createDirectories(out);
        int factor = quick ? 2 : 1;
        List<XYChart> relCharts = new ArrayList<>(), flipCharts = new ArrayList<>();
        StringBuilder table = new StringBuilder("| scene | method | render CPU | samples a pixel (mean) | relMSE | FLIP |\n"
                + "|---|---|--:|--:|--:|--:|\n");
        for (Subject s : SUBJECTS) {
            Path dir = Path.of("src/test/resources/reference-pt");
            RenderScene compiled = RenderScene.compile(SceneLoader.load(dir.resolve(s.name + ".yaml")),
                    new RenderSettings(Shading.COOK_TORRANCE, 64, 0.01, 1e-9).withTransport(s.transport));
            FrameBuffer reference = PfmReader.read(dir.resolve(s.name + ".pfm"));
            int w = s.width / factor, h = s.height / factor;
            reference = ImageErrors.averaged(reference, reference.width() / w);
            List<Point> uniform = new ArrayList<>(), adaptive = new ArrayList<>();
            try (Tracer tracer = new Tracer(THREADS)) {
                FrameBuffer frame = new FrameBuffer(w, h);
                tracer.render(compiled, frame, 16, 7, 8); // the JIT warmed up, not timed
                for (int spp : UNIFORM) {
                    long before = tracer.renderCpuNanos();
                    tracer.render(compiled, frame, spp, 0, 8);
                    long cpu = tracer.renderCpuNanos() - before;
                    uniform.add(point("uniform " + spp, cpu, spp, frame, reference));
                }
                for (double t : THRESHOLDS) {
                    Convergence c = new Convergence(w, h, t, CAP);
                    long before = tracer.renderCpuNanos();
                    c.refine(tracer, compiled, frame, 8, () -> { });
                    long cpu = tracer.renderCpuNanos() - before;
                    c.writeAverage(frame);
                    adaptive.add(point(String.format(Locale.ROOT, "noise %s %%", percent(t)), cpu,
                            c.samplesSpent() / (double) (w * h), frame, reference));
                    if (t == 0.02 && !quick && s.name.equals("lamp-and-frost")) {
                        samplesPicture(frame, c, out.resolve("adaptive-samples.png"));
                    }
                }
            }
            String title = s.name + (s.transport == LightTransport.BDPT ? " (bdpt)" : "");
            relCharts.add(chart(title, "relMSE", uniform, adaptive, true));
            flipCharts.add(chart(title, "mean FLIP", uniform, adaptive, false));
            for (List<Point> points : List.of(uniform, adaptive)) {
                for (Point p : points) {
                    table.append(String.format(Locale.ROOT, "| %s | %s | %.0f ms | %.1f | %.2e | %.4f |%n", s.name,
                            p.method, p.cpuMs, p.meanSpp, p.relMse, p.flip));
                }
            }
            System.err.println("glint: " + s.name + " done");
        }
        List<XYChart> all = new ArrayList<>(relCharts);
        all.addAll(flipCharts);
        Charts.save(all, 2, SUBJECTS.size(), out.resolve("accuracy-adaptive.png"));
        System.out.print(table);
    }

    /**
     * The window's noise readout ({@link Convergence#relativeNoise}) on sky-and-sun at 200 x 150 at 16, 64, 256 and
     * 1024 samples a pixel, every pixel sampled (no threshold): it should halve as the samples quadruple.
     */
    private static void readout() throws Exception {
        Path dir = Path.of("src/test/resources/reference-pt");
        for (String name : List.of("sky-and-sun", "bounce-box")) {
            RenderScene compiled = RenderScene.compile(SceneLoader.load(dir.resolve(name + ".yaml")),
                    new RenderSettings(Shading.COOK_TORRANCE, 64, 0.01, 1e-9).withTransport(LightTransport.PATH));
            Convergence c = new Convergence(200, 150, 0, 1024);
            StringBuilder line = new StringBuilder(name + ":");
            try (Tracer tracer = new Tracer(THREADS)) {
                c.refine(tracer, compiled, new FrameBuffer(200, 150), 8, () -> {
                    if (c.passes() == 16 || c.passes() == 64 || c.passes() == 256 || c.passes() == 1024) {
                        line.append(String.format(Locale.ROOT, " %d: %.2f %%", c.passes(), 100 * c.relativeNoise()));
                    }
                });
            }
            System.out.println(line);
        }
    }

    private static Point point(String method, long cpuNanos, double meanSpp, FrameBuffer frame,
                               FrameBuffer reference) {
        return new Point(method, cpuNanos / 1e6, meanSpp, RelativeMse.of(frame, reference), Flip.of(frame, reference));
    }

    private static XYChart chart(String title, String metric, List<Point> uniform, List<Point> adaptive,
                                 boolean legend) {
        XYChart chart = Charts.chart(title, "render CPU, ms (2 threads, 200 x 150)", metric, true, true, 420, 360);
        Charts.line(chart, "uniform 16 to 1024 spp", cpu(uniform), metric.equals("relMSE") ? rel(uniform)
                : flip(uniform), 1, false);
        Charts.line(chart, "adaptive, noise 10 % to 1 %", cpu(adaptive), metric.equals("relMSE") ? rel(adaptive)
                : flip(adaptive), 0, false);
        if (legend) {
            Charts.legendInside(chart, Styler.LegendPosition.InsideNE);
        } else {
            chart.getStyler().setLegendVisible(false);
        }
        return chart;
    }

    private static double[] cpu(List<Point> points) {
        return points.stream().mapToDouble(Point::cpuMs).toArray();
    }

    private static double[] rel(List<Point> points) {
        return points.stream().mapToDouble(Point::relMse).toArray();
    }

    private static double[] flip(List<Point> points) {
        return points.stream().mapToDouble(Point::flip).toArray();
    }

    private static String percent(double fraction) {
        return new java.math.BigDecimal(Double.toString(100 * fraction)).stripTrailingZeros().toPlainString();
    }

    /** The image beside a map of its samples a pixel, 64 (black) to the cap (white) on a log scale. */
    private static void samplesPicture(FrameBuffer frame, Convergence c, Path file) throws java.io.IOException {
        int w = frame.width(), h = frame.height(), scale = 2;
        BufferedImage picture = ImageWriter.toImage(frame, ViewTransform.DEFAULT);
        BufferedImage out = new BufferedImage(2 * w * scale + 8, h * scale + 22, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = out.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, out.getWidth(), out.getHeight());
        g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR);
        g.drawImage(picture, 0, 0, w * scale, h * scale, null);
        BufferedImage map = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        double low = Math.log(Convergence.MIN_ROUNDS * Convergence.ROUND), high = Math.log(c.cap());
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double t = (Math.log(Math.max(1, c.samples(y * w + x))) - low) / (high - low);
                int v = (int) Math.round(255 * Math.max(0, Math.min(1, t)));
                map.setRGB(x, y, v << 16 | v << 8 | v);
            }
        }
        g.drawImage(map, w * scale + 8, 0, w * scale, h * scale, null);
        g.setColor(Color.BLACK);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        g.drawString(String.format(Locale.ROOT, "noise 2 %%: %.0f samples a pixel on average", c.samplesSpent()
                / (double) (w * h)), 4, h * scale + 16);
        g.drawString("samples a pixel: 64 (black) to " + c.cap() + " (white), log scale", w * scale + 12,
                h * scale + 16);
        g.dispose();
        ImageIO.write(out, "png", file.toFile());
    }
}
