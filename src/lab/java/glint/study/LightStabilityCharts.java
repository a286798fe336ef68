package glint.study;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler.LegendPosition;
import org.knowm.xchart.style.markers.SeriesMarkers;

/** The charts of lights with a size in the stability study (stability.md, section 7). */
final class LightStabilityCharts {

    /** Where an error of exactly 0 is drawn on a log axis. */
    static final double ZERO = 1e-19;

    private LightStabilityCharts() {
    }

    /** The relative error of each form against r / d, and the irradiance a sample stands for. */
    static void cone(ConeWidth.Row[] rows, Path file) throws IOException {
        int n = rows.length;
        double[] x = new double[n], textbook = new double[n], glint = new double[n], guide = new double[n],
                u = new double[n], tbIrradiance = new double[n], glIrradiance = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = rows[i].ratio();
            textbook[i] = Math.max(ZERO, rows[i].textbookError());
            glint[i] = Math.max(ZERO, rows[i].glintError());
            guide[i] = Math.min(1, ConeWidth.U / (x[i] * x[i]));
            u[i] = ConeWidth.U;
            tbIrradiance[i] = rows[i].textbookIrradiance();
            glIrradiance[i] = rows[i].glintIrradiance();
        }
        String xTitle = "r / d (radius over distance; a smaller or farther light to the left)";
        XYChart error = Charts.chart("relative error of 1 - cos theta_max (0 drawn at 1e-19)", xTitle, "relative error",
                true, true);
        Charts.line(error, "textbook 1 - sqrt(1 - r^2/d^2)", x, textbook, 0, false);
        Charts.line(error, "Glint: sin^2 / (1 + cos), through its sampler", x, glint, 1, false);
        Charts.line(error, "u d^2 / r^2", x, guide, 0, true).setMarker(SeriesMarkers.NONE);
        Charts.line(error, "u = 1.1e-16", x, u, 1, true).setMarker(SeriesMarkers.NONE);
        Charts.legendInside(error, LegendPosition.InsideNE);
        error.getStyler().setYAxisMin(ZERO / 2);
        error.getStyler().setYAxisMax(10.0);
        XYChart irradiance = Charts.chart("irradiance a light sample stands for / (c I / d^2)", xTitle, "ratio", true,
                false);
        Charts.line(irradiance, "textbook", x, tbIrradiance, 0, false);
        Charts.line(irradiance, "Glint", x, glIrradiance, 1, false);
        Charts.legendInside(irradiance, LegendPosition.InsideNE);
        irradiance.getStyler().setYAxisMin(0.0);
        irradiance.getStyler().setYAxisMax(2.5);
        Charts.save(List.of(error, irradiance), 1, 2, file);
    }

    /** Per radius, largest sample / mean (solid) and std / mean (dashed) of each method against roughness. */
    static void fireflies(double[] radii, double[] roughness, String[] labels, LightStability.Cell[][] cells, Path file)
            throws IOException {
        List<XYChart> charts = new ArrayList<>();
        for (int r = 0; r < radii.length; r++) {
            XYChart c = Charts.chart("sphere light of radius " + Numbers.fixed(radii[r], 3)
                    + (r == 0 ? " (solid: largest / mean, dashed: std / mean)" : ""), "roughness of the metal wall",
                    "ratio to the mean", true, true, 640, 420);
            for (int m = 0; m < labels.length; m++) {
                double[] max = new double[roughness.length], std = new double[roughness.length];
                for (int g = 0; g < roughness.length; g++) {
                    max[g] = cells[r][g].methods()[m].maxOverMean();
                    std[g] = cells[r][g].methods()[m].relativeStd();
                }
                XYSeries solid = Charts.line(c, labels[m], roughness, max, m, false);
                XYSeries dashed = Charts.line(c, labels[m] + ", std", roughness, std, m, true);
                dashed.setShowInLegend(false);
                if (m == 0) {
                    solid.setMarker(SeriesMarkers.DIAMOND);
                    dashed.setMarker(SeriesMarkers.DIAMOND);
                }
            }
            Charts.legendInside(c, LegendPosition.InsideNE);
            c.getStyler().setLegendVisible(r == 0);
            c.getStyler().setYAxisMin(1.0);
            c.getStyler().setYAxisMax(1e6);
            charts.add(c);
        }
        Charts.save(charts, 2, 2, file);
    }
}
