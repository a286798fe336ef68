package glint.study;

import java.awt.BasicStroke;
import java.awt.Color;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.ToDoubleFunction;
import org.knowm.xchart.AnnotationText;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * Error against frame time, log-log, one panel per scene plus one for the geometric mean over the
 * scenes. Each knob's sweep from the shipped default is a line (depth, samples, min_weight), the other
 * configurations are points, the shipped default a diamond, and the Pareto front (2 % tolerance) a
 * broad band under them with its points named.
 */
final class AccuracyChart {

    /** A point joins the drawn front only if it lowers the error by at least this fraction. */
    static final double FRONT_TOLERANCE = 0.02;

    private AccuracyChart() {
    }

    static void write(List<List<Measurement>> panels, List<String> titles, String errorName,
                      ToDoubleFunction<Measurement> error, Path file) throws IOException {
        List<XYChart> charts = new ArrayList<>();
        for (int p = 0; p < panels.size(); p++) {
            charts.add(panel(titles.get(p), panels.get(p), errorName, error));
        }
        int columns = charts.size() % 2 == 0 ? 2 : 1; // the grid must be full
        int rows = (charts.size() + columns - 1) / columns;
        Charts.save(charts, rows, columns, file);
    }

    private static XYChart panel(String title, List<Measurement> ms, String errorName,
                                 ToDoubleFunction<Measurement> error) {
        XYChart chart = Charts.chart(title, "CPU time per frame, ms (median, all render threads)", errorName, true,
                true, 820);
        chart.getStyler().setLegendFont(new java.awt.Font(java.awt.Font.SANS_SERIF, java.awt.Font.PLAIN, 10));
        chart.getStyler().setMarkerSize(7);
        double[] x = new double[ms.size()], y = new double[ms.size()];
        for (int i = 0; i < ms.size(); i++) {
            x[i] = ms.get(i).cpuMillis();
            y[i] = Math.max(1e-12, error.applyAsDouble(ms.get(i)));
        }
        List<Integer> front = Pareto.front(x, y, FRONT_TOLERANCE);
        XYSeries band = chart.addSeries("Pareto front", pick(x, front), pick(y, front));
        band.setLineColor(new Color(255, 120, 120, 110));
        band.setLineStyle(new BasicStroke(9f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        band.setMarker(SeriesMarkers.NONE);
        Labels labels = new Labels(chart);
        for (int i : front) {
            labels.add(ms.get(i).config().label(), x[i], y[i] / 1.45);
        }

        StudyConfig.Knob[] swept = {StudyConfig.Knob.DEPTH, StudyConfig.Knob.SAMPLES, StudyConfig.Knob.MIN_WEIGHT};
        StudyConfig centre = StudyConfig.shipped();
        String weight = "w" + Numbers.sci(centre.minWeight());
        String[] names = {"depth 1..24 (s" + centre.samples() + " " + weight + ")",
                "samples 1..64 (d" + centre.depth() + " " + weight + ")",
                "min_weight 0.001..0.1 (d" + centre.depth() + " s" + centre.samples() + ")"};
        int[] colors = {1, 3, 4};
        for (int k = 0; k < swept.length; k++) {
            List<Integer> members = new ArrayList<>();
            for (int i = 0; i < ms.size(); i++) {
                StudyConfig.Knob knob = ms.get(i).config().knob();
                if (knob == swept[k] || knob == StudyConfig.Knob.NONE) {
                    members.add(i);
                }
            }
            if (members.size() < 2) {
                continue;
            }
            final StudyConfig.Knob knob = swept[k];
            members.sort(Comparator.comparingDouble(i -> knobValue(ms.get(i).config(), knob)));
            Charts.line(chart, names[k], pick(x, members), pick(y, members), colors[k], false)
                    .setMarker(SeriesMarkers.CIRCLE);
            for (int i : members) {
                if (ms.get(i).config().knob() != StudyConfig.Knob.NONE && !front.contains(i)) {
                    labels.add(ms.get(i).config().knobLabel(), x[i], y[i] * 1.45);
                }
            }
        }
        List<Integer> others = new ArrayList<>();
        for (int i = 0; i < ms.size(); i++) {
            StudyConfig.Knob knob = ms.get(i).config().knob();
            if (knob == StudyConfig.Knob.SEVERAL || knob == StudyConfig.Knob.SHADING
                    || knob == StudyConfig.Knob.FRESNEL || knob == StudyConfig.Knob.PRUNING) {
                others.add(i);
            }
        }
        if (!others.isEmpty()) {
            XYSeries s = chart.addSeries("other (table)", pick(x, others), pick(y, others));
            s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
            s.setMarker(SeriesMarkers.SQUARE);
            s.setMarkerColor(new Color(0x777777));
            for (int i : others) {
                StudyConfig c = ms.get(i).config();
                if (c.knob() != StudyConfig.Knob.SEVERAL && !front.contains(i)) {
                    labels.add(c.knobLabel(), x[i], y[i] * 1.45);
                }
            }
        }
        StudyConfig shipped = StudyConfig.shipped();
        for (int i = 0; i < ms.size(); i++) {
            if (ms.get(i).config().equals(shipped)) {
                XYSeries s = chart.addSeries("shipped default " + shipped.label(), new double[] {x[i]},
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

    private static double knobValue(StudyConfig c, StudyConfig.Knob knob) {
        return switch (knob) {
            case DEPTH -> c.depth();
            case SAMPLES -> c.samples();
            default -> c.minWeight();
        };
    }

    private static double[] pick(double[] values, List<Integer> indices) {
        double[] out = new double[indices.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = values[indices.get(i)];
        }
        return out;
    }
}
