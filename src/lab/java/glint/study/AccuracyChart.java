package glint.study;

import java.awt.BasicStroke;
import java.awt.Color;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.Function;
import java.util.function.Predicate;
import java.util.function.ToDoubleFunction;
import org.knowm.xchart.AnnotationText;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * Error against render CPU time per frame, log-log, in panels side by side. Each series (a family
 * of methods along one knob) is a line, points of no series are grey squares, the shipped default a
 * black diamond, and the Pareto front (2 % tolerance) a broad red band under them with its points
 * named.
 */
final class AccuracyChart {

    /** A point joins the drawn front only if it lowers the error by at least this fraction. */
    static final double FRONT_TOLERANCE = 0.02;

    /**
     * A line of the chart: the configurations it joins, in the order of {@code order}, each point
     * named by {@code pointLabel} (unless it is on the front, which names its own).
     */
    record Series(String name, Predicate<StudyConfig> member, ToDoubleFunction<StudyConfig> order,
                  Function<StudyConfig, String> pointLabel, int color) {
    }

    /** An error a panel shows: its axis title and its value. */
    record Metric(String name, ToDoubleFunction<Measurement> value) {
        static final Metric REL_MSE = new Metric("relative MSE", Measurement::relMse);
        static final Metric SSIM = new Metric("1 - SSIM", m -> 1 - m.ssim());
        static final Metric FLIP = new Metric("mean FLIP", Measurement::flip);
    }

    /** One panel: a title, its points and the error it shows. */
    record Panel(String title, List<Measurement> points, Metric metric) {
    }

    private AccuracyChart() {
    }

    /** The methods against physics: ray casting, Whitted along depth and along samples, the path and bdpt tracers. */
    static List<Series> methodSeries() {
        StudyConfig shipped = StudyConfig.shipped();
        return List.of(
                new Series("ray casting s1-64", c -> c.method() == StudyConfig.Method.RAY_CASTING
                        && isWhittedAlong(c, StudyConfig.Knob.SAMPLES, 1), StudyConfig::samples, c -> "s" + c.samples(), 2),
                new Series("Whitted d1-" + shipped.depth() + " s" + shipped.samples(),
                        c -> isWhittedAlong(c, StudyConfig.Knob.DEPTH, shipped.depth()), StudyConfig::depth,
                        c -> "d" + c.depth(), 1),
                new Series("Whitted d" + shipped.depth() + " s1-64",
                        c -> isWhittedAlong(c, StudyConfig.Knob.SAMPLES, shipped.depth()), StudyConfig::samples,
                        c -> "s" + c.samples(), 3),
                new Series("path s1-1024", StudyConfig::isPath, StudyConfig::samples,
                        c -> "s" + c.samples(), 0),
                new Series("bdpt s1-256", c -> c.method() == StudyConfig.Method.BDPT, StudyConfig::samples,
                        c -> "s" + c.samples(), 4));
    }

    /** Whitted against its own converged image: along depth, samples and min_weight from the shipped default. */
    static List<Series> whittedSeries() {
        StudyConfig shipped = StudyConfig.shipped();
        String weight = "w" + Numbers.sci(shipped.minWeight());
        return List.of(
                new Series("depth 1.." + shipped.depth() + " (s" + shipped.samples() + " " + weight + ")",
                        c -> isWhittedAlong(c, StudyConfig.Knob.DEPTH, shipped.depth()), StudyConfig::depth,
                        StudyConfig::knobLabel, 1),
                new Series("samples 1..64 (d" + shipped.depth() + " " + weight + ")",
                        c -> isWhittedAlong(c, StudyConfig.Knob.SAMPLES, shipped.depth()), StudyConfig::samples,
                        StudyConfig::knobLabel, 3),
                new Series("min_weight 0.001..0.1 (d" + shipped.depth() + " s" + shipped.samples() + ")",
                        c -> !c.isPath() && (c.knob() == StudyConfig.Knob.MIN_WEIGHT || c.knob() == StudyConfig.Knob.NONE),
                        StudyConfig::minWeight, StudyConfig::knobLabel, 4));
    }

    /**
     * Whitted with the shipped knobs but for {@code knob}: along depth (at the shipped samples), or
     * along samples at depth {@code depth}.
     */
    private static boolean isWhittedAlong(StudyConfig c, StudyConfig.Knob knob, int depth) {
        StudyConfig shipped = StudyConfig.shipped();
        if (c.isPath() || !c.equals(StudyConfig.whitted(c.depth(), c.samples()))) {
            return false;
        }
        return knob == StudyConfig.Knob.DEPTH ? c.samples() == shipped.samples() : c.depth() == depth;
    }

    /**
     * Writes the panels in a grid of {@code columns}, each with the same series, the front named by
     * {@code frontLabel}; with {@code legendBelow} each panel's legend goes under its plot (taller
     * panels), else into the plot's top right corner, which expensive and inaccurate methods leave empty.
     */
    static void write(List<Panel> panels, List<Series> series, Function<StudyConfig, String> frontLabel, int columns,
                      int panelWidth, boolean legendBelow, Path file) throws IOException {
        List<XYChart> charts = new ArrayList<>();
        for (Panel panel : panels) {
            charts.add(legendBelow
                    ? chart(panel, series, frontLabel, panelWidth, 620, Styler.LegendPosition.OutsideS)
                    : chart(panel, series, frontLabel, panelWidth, 520, Styler.LegendPosition.InsideNE));
        }
        int rows = (charts.size() + columns - 1) / columns;
        if (rows * columns != charts.size()) {
            throw new IllegalArgumentException(charts.size() + " panels do not fill " + rows + " x " + columns);
        }
        Charts.save(charts, rows, columns, file);
    }

    private static XYChart chart(Panel panel, List<Series> series, Function<StudyConfig, String> frontLabel, int width,
                                 int height, Styler.LegendPosition legend) {
        List<Measurement> ms = panel.points();
        XYChart chart = Charts.chart(panel.title(), "render CPU per frame, ms (both render threads)",
                panel.metric().name(), true, true, width, height);
        chart.getStyler().setLegendFont(new java.awt.Font(java.awt.Font.SANS_SERIF, java.awt.Font.PLAIN, 10));
        chart.getStyler().setLegendPosition(legend);
        chart.getStyler().setMarkerSize(6);
        double[] x = new double[ms.size()], y = new double[ms.size()];
        for (int i = 0; i < ms.size(); i++) {
            x[i] = ms.get(i).cpuMillis();
            y[i] = Math.max(1e-12, panel.metric().value().applyAsDouble(ms.get(i)));
        }
        // room for the labels above and below the points
        chart.getStyler().setXAxisMin(min(x) / 1.6);
        chart.getStyler().setXAxisMax(max(x) * 1.6);
        chart.getStyler().setYAxisMin(min(y) / 2.5);
        chart.getStyler().setYAxisMax(max(y) * (legend == Styler.LegendPosition.InsideNE ? 6 : 2.5));
        List<Integer> front = Pareto.front(x, y, FRONT_TOLERANCE);
        XYSeries band = chart.addSeries("Pareto front", pick(x, front), pick(y, front));
        band.setLineColor(new Color(255, 120, 120, 110));
        band.setLineStyle(new BasicStroke(9f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        band.setMarker(SeriesMarkers.NONE);
        Labels labels = new Labels(chart);
        for (int i : front) {
            labels.add(frontLabel.apply(ms.get(i).config()), x[i], y[i] / 1.5);
        }
        List<Integer> inNoSeries = new ArrayList<>();
        for (int i = 0; i < ms.size(); i++) {
            inNoSeries.add(i);
        }
        for (Series s : series) {
            List<Integer> members = new ArrayList<>();
            for (int i = 0; i < ms.size(); i++) {
                if (s.member().test(ms.get(i).config())) {
                    members.add(i);
                }
            }
            inNoSeries.removeAll(members);
            if (members.isEmpty()) {
                continue;
            }
            members.sort(Comparator.comparingDouble(i -> s.order().applyAsDouble(ms.get(i).config())));
            Charts.line(chart, s.name(), pick(x, members), pick(y, members), s.color(), false)
                    .setMarker(SeriesMarkers.CIRCLE);
            for (int i : members) {
                if (!front.contains(i)) {
                    labels.add(s.pointLabel().apply(ms.get(i).config()), x[i], y[i] * 1.5);
                }
            }
        }
        if (!inNoSeries.isEmpty()) {
            XYSeries s = chart.addSeries("other (table)", pick(x, inNoSeries), pick(y, inNoSeries));
            s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
            s.setMarker(SeriesMarkers.SQUARE);
            s.setMarkerColor(new Color(0x777777));
            for (int i : inNoSeries) {
                if (!front.contains(i)) {
                    labels.add(ms.get(i).config().knobLabel(), x[i], y[i] * 1.5);
                }
            }
        }
        StudyConfig shipped = StudyConfig.shipped();
        for (int i = 0; i < ms.size(); i++) {
            if (ms.get(i).config().equals(shipped)) {
                XYSeries s = chart.addSeries("shipped: Whitted " + shipped.label(), new double[] {x[i]},
                        new double[] {y[i]});
                s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
                s.setMarker(SeriesMarkers.DIAMOND);
                s.setMarkerColor(Color.BLACK);
            }
        }
        return chart;
    }

    /**
     * Point labels that do not overlap: on log-log axes a label is dropped when one already placed is
     * closer than a quarter decade in time and a fifth of a decade in error (the table lists them all).
     */
    private static final class Labels {
        private final XYChart chart;
        private final List<double[]> placed = new ArrayList<>();

        Labels(XYChart chart) {
            this.chart = chart;
        }

        void add(String text, double x, double y) {
            double lx = Math.log10(x), ly = Math.log10(y);
            for (double[] p : placed) {
                if (Math.abs(p[0] - lx) < 0.25 && Math.abs(p[1] - ly) < 0.2) {
                    return;
                }
            }
            placed.add(new double[] {lx, ly});
            chart.addAnnotation(new AnnotationText(text, x, y, false));
        }
    }

    private static double min(double[] values) {
        double m = Double.POSITIVE_INFINITY;
        for (double v : values) {
            m = Math.min(m, v);
        }
        return m;
    }

    private static double max(double[] values) {
        double m = 0;
        for (double v : values) {
            m = Math.max(m, v);
        }
        return m;
    }

    private static double[] pick(double[] values, List<Integer> indices) {
        double[] out = new double[indices.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = values[indices.get(i)];
        }
        return out;
    }
}
