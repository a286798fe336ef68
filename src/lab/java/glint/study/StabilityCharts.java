package glint.study;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler.LegendPosition;
import org.knowm.xchart.style.markers.SeriesMarkers;

/** The charts of the stability study, one PNG per failure, the textbook method beside Glint's. */
final class StabilityCharts {

    private StabilityCharts() {
    }

    /** Two panels: pixels with a wrong hit/miss decision, and pixels wrong in any way, against the distance. */
    static void sphere(String what, String xTitle, double[] x, Map<SphereMethod, SphereErrors[]> errors, Path file)
            throws IOException {
        XYChart hitMiss = Charts.chart(what + ": wrong hit/miss", xTitle, "fraction of pixels", true, false);
        XYChart any = Charts.chart(what + ": any error (hit/miss or distance)", xTitle,
                "fraction of pixels", true, false);
        int color = 0;
        for (Map.Entry<SphereMethod, SphereErrors[]> e : errors.entrySet()) {
            double[] y1 = new double[x.length], y2 = new double[x.length];
            for (int i = 0; i < x.length; i++) {
                y1[i] = e.getValue()[i].hitMissFraction();
                y2[i] = e.getValue()[i].wrongFraction();
            }
            boolean dashed = e.getKey().isFloat();
            Charts.line(hitMiss, e.getKey().label(), x, y1, color, dashed);
            Charts.line(any, e.getKey().label(), x, y2, color, dashed);
            color++;
        }
        for (XYChart c : List.of(hitMiss, any)) {
            Charts.legendInside(c, LegendPosition.InsideNW);
            c.getStyler().setYAxisMin(0.0);
            c.getStyler().setYAxisMax(1.0);
            c.getStyler().setMarkerSize(5);
        }
        Charts.save(List.of(hitMiss, any), 1, 2, file);
    }

    /**
     * Acne (lit shown dark, not explained by the offset), missed shadows and lit pixels shadowed by the
     * offset itself against the move, and acne on a ground sphere against its radius: a 2 x 2 grid.
     */
    static void offsets(double[] s, double[] radii, List<OffsetMethod> methods, OffsetErrors[][] contact,
                        OffsetErrors[][] ground, Path file) throws IOException {
        String moved = "contact scene moved by (s, s, s): s";
        XYChart acne = Charts.chart("acne: lit pixels shown dark", moved, "fraction of lit pixels", true, false);
        XYChart missed = Charts.chart("missed cast shadows", moved, "fraction of shadow pixels", true, false);
        XYChart overshoot = Charts.chart("lit pixels shadowed by the offset itself", moved,
                "fraction of lit pixels", true, false);
        XYChart sphere = Charts.chart("ground sphere, top at the origin: acne", "sphere radius",
                "fraction of lit pixels", true, false);
        for (int m = 0; m < methods.size(); m++) {
            double[] a = new double[s.length], b = new double[s.length], c = new double[s.length];
            for (int i = 0; i < s.length; i++) {
                a[i] = contact[m][i].acneFraction();
                b[i] = contact[m][i].missedFraction();
                c[i] = contact[m][i].overshootFraction();
            }
            double[] g = new double[radii.length];
            for (int i = 0; i < radii.length; i++) {
                g[i] = ground[m][i].acneFraction();
            }
            boolean dashed = methods.get(m) instanceof OffsetMethod.Fixed;
            Charts.line(acne, methods.get(m).label(), s, a, m, dashed);
            Charts.line(missed, methods.get(m).label(), s, b, m, dashed);
            Charts.line(overshoot, methods.get(m).label(), s, c, m, dashed);
            Charts.line(sphere, methods.get(m).label(), radii, g, m, dashed);
        }
        for (XYChart c : List.of(acne, missed, overshoot, sphere)) {
            Charts.legendInside(c, LegendPosition.InsideNW);
            c.getStyler().setYAxisMin(0.0);
            c.getStyler().setYAxisMax(1.0);
            c.getStyler().setMarkerSize(5);
        }
        Charts.save(List.of(acne, missed, overshoot, sphere), 2, 2, file);
    }

    static void fresnel(double[] angles, Path file) throws IOException {
        int n = angles.length;
        double[] eo = new double[n], so = new double[n], ei = new double[n], si = new double[n], wi = new double[n];
        for (int i = 0; i < n; i++) {
            eo[i] = FresnelCurves.exactOutside(angles[i]);
            so[i] = FresnelCurves.schlickOutside(angles[i]);
            ei[i] = FresnelCurves.exactInside(angles[i]);
            si[i] = FresnelCurves.schlickInside(angles[i]);
            wi[i] = FresnelCurves.schlickWrongCosineInside(angles[i]);
        }
        XYChart outside = Charts.chart("from outside (air to glass, n = 1.5)", "angle of incidence, degrees",
                "reflectance", false, false);
        Charts.line(outside, "exact Fresnel (Glint)", angles, eo, 1, false).setMarker(SeriesMarkers.NONE);
        Charts.line(outside, "Schlick", angles, so, 0, true).setMarker(SeriesMarkers.NONE);
        XYChart inside = Charts.chart("from inside (glass to air), critical angle "
                + Numbers.fixed(FresnelCurves.criticalAngleDegrees(), 2) + " deg", "angle of incidence, degrees",
                "reflectance", false, false);
        Charts.line(inside, "exact Fresnel (Glint)", angles, ei, 1, false).setMarker(SeriesMarkers.NONE);
        Charts.line(inside, "Schlick, air-side cosine, TIR (Glint's option)", angles, si, 3, true)
                .setMarker(SeriesMarkers.NONE);
        Charts.line(inside, "Schlick, incident cosine (textbook slip)", angles, wi, 0, true)
                .setMarker(SeriesMarkers.NONE);
        for (XYChart c : List.of(outside, inside)) {
            Charts.legendInside(c, LegendPosition.InsideNW);
            c.getStyler().setXAxisTickMarkSpacingHint(70);
            c.getStyler().setYAxisMin(0.0);
            c.getStyler().setYAxisMax(1.05);
            c.getStyler().setXAxisMin(0.0);
            c.getStyler().setXAxisMax(90.0);
        }
        Charts.save(List.of(outside, inside), 1, 2, file);
    }

    static void microfacet(double[] viewDegrees, double[] roughness, double[][] glint, double[][] textbook, Path file)
            throws IOException {
        XYChart left = Charts.chart("Glint: GGX, height-correlated Smith", "view angle from the normal, degrees",
                "directional albedo (F = 1)", false, false);
        XYChart right = Charts.chart("textbook: Beckmann, V-groove masking", "view angle from the normal, degrees",
                "directional albedo (F = 1)", false, false);
        for (int r = 0; r < roughness.length; r++) {
            String name = "roughness " + Numbers.sci(roughness[r]).replace("e0", "");
            Charts.line(left, name, viewDegrees, glint[r], r, false).setMarker(SeriesMarkers.NONE);
            Charts.line(right, name, viewDegrees, textbook[r], r, false).setMarker(SeriesMarkers.NONE);
        }
        for (XYChart c : List.of(left, right)) {
            Charts.legendInside(c, LegendPosition.InsideSW);
            c.getStyler().setXAxisTickMarkSpacingHint(70);
            c.getStyler().setYAxisMin(0.0);
            c.getStyler().setYAxisMax(1.1);
        }
        Charts.save(List.of(left, right), 1, 2, file);
    }

    /** |(|q| - 1)| against turns, log-log; exact zeros are drawn at 1e-17. */
    static void quaternion(long[] turns, Map<String, double[]> errors, Path file) throws IOException {
        XYChart chart = Charts.chart("camera quaternion: | |q| - 1 | after n turns (0 drawn at 1e-17)", "turns",
                "| |q| - 1 |", true, true, 900);
        double[] x = new double[turns.length];
        for (int i = 0; i < turns.length; i++) {
            x[i] = turns[i];
        }
        int color = 0;
        for (Map.Entry<String, double[]> e : errors.entrySet()) {
            double[] y = new double[turns.length];
            for (int i = 0; i < turns.length; i++) {
                y[i] = Math.max(1e-17, Math.abs(e.getValue()[i]));
            }
            XYSeries s = Charts.line(chart, e.getKey(), x, y, color, e.getKey().contains("float"));
            s.setMarker(SeriesMarkers.CIRCLE);
            color++;
        }
        Charts.legendInside(chart, LegendPosition.InsideNW);
        chart.getStyler().setYAxisMin(1e-17);
        chart.getStyler().setYAxisMax(1e-1);
        Charts.save(List.of(chart), 1, 1, file);
    }
}
