package glint.study;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/** XChart helpers shared by the study charts: one look, PNG output, panels side by side. */
final class Charts {

    static final Color[] PALETTE = {
        new Color(0xD62728), new Color(0x1F77B4), new Color(0xFF7F0E), new Color(0x2CA02C),
        new Color(0x9467BD), new Color(0x8C564B), new Color(0x17BECF)};

    private Charts() {
    }

    static XYChart chart(String title, String xTitle, String yTitle, boolean logX, boolean logY) {
        return chart(title, xTitle, yTitle, logX, logY, 640);
    }

    static XYChart chart(String title, String xTitle, String yTitle, boolean logX, boolean logY, int width) {
        return chart(title, xTitle, yTitle, logX, logY, width, 460);
    }

    static XYChart chart(String title, String xTitle, String yTitle, boolean logX, boolean logY, int width,
                         int height) {
        XYChart chart = new XYChartBuilder().width(width).height(height).title(title).xAxisTitle(xTitle)
                .yAxisTitle(yTitle).build();
        org.knowm.xchart.style.XYStyler s = chart.getStyler();
        chart.getStyler().setXAxisLogarithmic(logX);
        chart.getStyler().setYAxisLogarithmic(logY);
        chart.getStyler().setDefaultSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line);
        s.setChartBackgroundColor(Color.WHITE);
        s.setPlotBackgroundColor(Color.WHITE);
        s.setPlotGridLinesColor(new Color(0xE4E4E4));
        s.setPlotGridLinesStroke(new BasicStroke(0.6f));
        s.setLegendPosition(Styler.LegendPosition.OutsideE);
        s.setLegendBackgroundColor(new Color(255, 255, 255, 220));
        s.setChartTitleFont(new Font(Font.SANS_SERIF, Font.BOLD, 14));
        s.setLegendFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        s.setAnnotationTextFont(new Font(Font.SANS_SERIF, Font.PLAIN, 10));
        s.setSeriesColors(PALETTE);
        s.setAntiAlias(true);
        return chart;
    }

    /** Moves the legend into the plot, at the given corner. */
    static void legendInside(XYChart chart, Styler.LegendPosition corner) {
        chart.getStyler().setLegendPosition(corner);
    }

    /** A line with markers. */
    static XYSeries line(XYChart chart, String name, double[] x, double[] y, int colorIndex, boolean dashed) {
        XYSeries series = chart.addSeries(name, x, y);
        series.setLineColor(PALETTE[colorIndex % PALETTE.length]);
        series.setMarkerColor(PALETTE[colorIndex % PALETTE.length]);
        series.setMarker(SeriesMarkers.CIRCLE);
        if (dashed) {
            series.setLineStyle(new BasicStroke(1.6f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10,
                    new float[] {6, 4}, 0));
        } else {
            series.setLineStyle(new BasicStroke(1.8f));
        }
        return series;
    }

    /** Saves charts in a grid of {@code rows} x {@code columns} panels as one PNG. */
    static void save(List<XYChart> charts, int rows, int columns, Path file) throws IOException {
        if (file.getParent() != null) {
            Files.createDirectories(file.getParent());
        }
        String name = file.toString();
        String stem = name.endsWith(".png") ? name.substring(0, name.length() - 4) : name;
        BitmapEncoder.saveBitmap(charts, rows, columns, stem, BitmapEncoder.BitmapFormat.PNG);
    }
}
