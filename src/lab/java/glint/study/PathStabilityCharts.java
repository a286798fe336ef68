package glint.study;

import glint.shading.Microfacet;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler.LegendPosition;
import org.knowm.xchart.style.markers.SeriesMarkers;

/** The charts of the path integrator's stability study (stability.md, section 6). */
final class PathStabilityCharts {

    private PathStabilityCharts() {
    }

    /** Largest weight, samples lost and the weight's spread against the view's cosine, both samplings. */
    static void ggx(double[] cosines, double[] roughness, GgxSampling.Stats[][] glint, GgxSampling.Stats[][] textbook,
                    Path file) throws IOException {
        String x = "cosine of the view to the normal (grazing to the left)";
        XYChart max = Charts.chart("largest weight f cos / pdf (F = 1)", x, "weight", true, true);
        XYChart lost = Charts.chart("samples lost: wi below the surface (solid: Glint, dashed: textbook)", x,
                "fraction of samples", true, false);
        XYChart spread = Charts.chart("std of one sample's weight / its mean", x, "relative std", true, false);
        for (int r = 0; r < roughness.length; r++) {
            int n = cosines.length;
            double[][] g = new double[3][n], t = new double[3][n];
            for (int i = 0; i < n; i++) {
                g[0][i] = glint[r][i].maxWeight();
                t[0][i] = textbook[r][i].maxWeight();
                g[1][i] = glint[r][i].lostFraction();
                t[1][i] = textbook[r][i].lostFraction();
                g[2][i] = glint[r][i].relativeStd();
                t[2][i] = textbook[r][i].relativeStd();
            }
            String name = "roughness " + Numbers.fixed(roughness[r], 4);
            XYChart[] charts = {max, lost, spread};
            for (int k = 0; k < 3; k++) {
                Charts.line(charts[k], name, cosines, g[k], r, false).setMarker(SeriesMarkers.NONE);
                XYSeries dashed = Charts.line(charts[k], "textbook, " + name, cosines, t[k], r, true);
                dashed.setMarker(SeriesMarkers.NONE);
                dashed.setShowInLegend(false);
            }
        }
        for (XYChart c : List.of(max, lost, spread)) {
            Charts.legendInside(c, LegendPosition.InsideNE);
            c.getStyler().setXAxisMin(1e-6);
            c.getStyler().setXAxisMax(1.0);
        }
        max.getStyler().setYAxisMin(0.5);
        max.getStyler().setLegendVisible(false);
        spread.getStyler().setLegendVisible(false);
        lost.getStyler().setYAxisMin(0.0);
        lost.getStyler().setYAxisMax(0.8);
        Charts.save(List.of(max, lost, spread), 1, 3, file);
    }

    /** The render's mean against the closed form, and its spread and largest sample, against roughness. */
    static void fireflies(double[] roughness, int[] budgets, double[][] mean, double[][] error, double directOverMirror,
                          double[] relativeStd, double[] maxOverMean, Path file) throws IOException {
        String x = "roughness of the metal wall";
        XYChart means = Charts.chart("mean radiance / mirror-image closed form (± 2 standard errors)", x, "ratio", true,
                false, 760);
        for (int b = 0; b < budgets.length; b++) {
            double[] bars = new double[roughness.length];
            for (int r = 0; r < roughness.length; r++) {
                bars[r] = 2 * error[b][r];
            }
            XYSeries s = means.addSeries(budgets[b] + " samples a pixel", roughness, mean[b], bars);
            s.setLineColor(Charts.PALETTE[b + 1]);
            s.setMarkerColor(Charts.PALETTE[b + 1]);
            s.setMarker(SeriesMarkers.CIRCLE);
        }
        double[] ends = {roughness[0], roughness[roughness.length - 1]};
        Charts.line(means, "mirror wall (closed form)", ends, new double[] {1, 1}, 3, true).setMarker(SeriesMarkers.NONE);
        Charts.line(means, "direct light alone", ends, new double[] {directOverMirror, directOverMirror}, 0, true)
                .setMarker(SeriesMarkers.NONE);
        double threshold = Math.sqrt(Microfacet.MIRROR_ALPHA);
        Charts.line(means, "delta mirror below roughness " + Numbers.fixed(threshold, 4),
                new double[] {threshold, threshold}, new double[] {0.5, 1.3}, 4, true).setMarker(SeriesMarkers.NONE);
        Charts.legendInside(means, LegendPosition.InsideSE);
        means.getStyler().setYAxisMin(0.5);
        means.getStyler().setYAxisMax(1.3);
        XYChart spread = Charts.chart("one sample, " + budgets[budgets.length - 1] + " samples a pixel", x,
                "ratio to the mean", true, true, 640);
        Charts.line(spread, "standard deviation / mean", roughness, relativeStd, 1, false);
        Charts.line(spread, "largest sample / mean", roughness, maxOverMean, 0, false);
        Charts.legendInside(spread, LegendPosition.InsideNE);
        Charts.save(List.of(means, spread), 1, 2, file);
    }

    /** The furnace's mean against the impact parameter, and a sample's spread over a black floor. */
    static void glass(double[] impacts, int[] hits, double[][] measured, double[] floorStd, int width, Path file)
            throws IOException {
        String x = "impact parameter b (pixel centre), radii";
        XYChart furnace = Charts.chart("furnace: pixel mean / sky", x, "ratio", false, false);
        for (int h = 0; h < hits.length; h++) {
            List<Double> bx = new ArrayList<>(), by = new ArrayList<>();
            for (int p = 0; p < impacts.length; p++) {
                if (impacts[p] < 1) {
                    bx.add(impacts[p]);
                    by.add(measured[h][p]);
                }
            }
            XYSeries dots = furnace.addSeries("measured, " + hits[h] + " hits", bx, by);
            dots.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
            dots.setMarkerColor(Charts.PALETTE[h]);
            dots.setMarker(SeriesMarkers.CIRCLE);
            double[] b = new double[200], expected = new double[200];
            for (int i = 0; i < b.length; i++) {
                b[i] = i / 200.0;
                expected[i] = 1 - GlassSky.truncated(b[i], hits[h]);
            }
            Charts.line(furnace, "1 - (1 - F) F^(hits - 2), " + hits[h] + " hits", b, expected, h, false)
                    .setMarker(SeriesMarkers.NONE);
        }
        Charts.legendInside(furnace, LegendPosition.InsideSW);
        furnace.getStyler().setMarkerSize(3);
        furnace.getStyler().setXAxisMin(0.0);
        furnace.getStyler().setXAxisMax(1.0);
        XYChart floor = Charts.chart("over a black floor: std of a sample / pixel mean", x, "relative std", false, false);
        List<Double> ux = new ArrayList<>(), uy = new ArrayList<>(), lx = new ArrayList<>(), ly = new ArrayList<>();
        for (int p = 0; p < impacts.length; p++) {
            if (impacts[p] < 1 && floorStd[p] > 0) {
                boolean upper = p / width < impacts.length / width / 2;
                (upper ? ux : lx).add(impacts[p]);
                (upper ? uy : ly).add(floorStd[p]);
            }
        }
        for (int k = 0; k < 2; k++) {
            XYSeries s = floor.addSeries(k == 0 ? "upper half of the ball" : "lower half", k == 0 ? ux : lx,
                    k == 0 ? uy : ly);
            s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
            s.setMarkerColor(Charts.PALETTE[k + 1]);
            s.setMarker(SeriesMarkers.CIRCLE);
        }
        Charts.legendInside(floor, LegendPosition.InsideNE);
        floor.getStyler().setMarkerSize(3);
        floor.getStyler().setXAxisMin(0.0);
        floor.getStyler().setXAxisMax(1.0);
        floor.getStyler().setYAxisMin(0.0);
        Charts.save(List.of(furnace, floor), 1, 2, file);
    }
}
