package glint.study;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Writes what the speed/accuracy study found into an output folder: one chart per scene against
 * physics (images/accuracy-SCENE.png: relMSE, 1 - SSIM and FLIP), one chart of Whitted against its
 * own converged image (images/accuracy-whitted.png), the generated sections of accuracy.md (the
 * verdict, the check of the reference, Whitted's table) and every method's table, in accuracy-tables.md.
 */
final class StudyOutput {

    /** Width of one panel of a chart, pixels. */
    private static final int PANEL_WIDTH = 600;

    private StudyOutput() {
    }

    static void write(Path out, List<SpeedAccuracy.SceneResult> results, String meta) throws IOException {
        Path images = out.resolve("images");
        Path doc = out.resolve("accuracy.md");
        List<AccuracyReport.Verdict> verdicts = new ArrayList<>();
        StringBuilder validation = new StringBuilder();
        StringBuilder tables = new StringBuilder(meta).append('\n');
        List<AccuracyChart.Panel> whittedPanels = new ArrayList<>();
        List<List<Measurement>> whitted = new ArrayList<>();
        for (SpeedAccuracy.SceneResult r : results) {
            String name = r.scene().name();
            List<AccuracyChart.Panel> panels = new ArrayList<>();
            for (AccuracyChart.Metric metric : List.of(AccuracyChart.Metric.REL_MSE, AccuracyChart.Metric.SSIM,
                    AccuracyChart.Metric.FLIP)) {
                panels.add(new AccuracyChart.Panel(name + ": " + metric.name() + " against physics", r.physics(), metric));
            }
            AccuracyChart.write(panels, AccuracyChart.methodSeries(), StudyConfig::methodLabel, panels.size(),
                    PANEL_WIDTH, true, images.resolve("accuracy-" + name + ".png"));
            verdicts.add(AccuracyReport.verdict(name, r.physics()));
            validation.append(r.validation());
            tables.append("#### ").append(name).append("\n\n").append(AccuracyReport.methodsTable(r.physics()))
                    .append('\n');
            whittedPanels.add(new AccuracyChart.Panel(name, r.whitted(), AccuracyChart.Metric.REL_MSE));
            whitted.add(r.whitted());
        }
        int columns = whittedPanels.size() % 2 == 0 ? 2 : 1;
        AccuracyChart.write(whittedPanels, AccuracyChart.whittedSeries(), StudyConfig::label, columns, PANEL_WIDTH + 160,
                false, images.resolve("accuracy-whitted.png"));
        GeneratedSection.write(doc, "accuracy-verdict", AccuracyReport.verdictTable(verdicts));
        if (validation.length() > 0) {
            GeneratedSection.write(doc, "accuracy-validation", PhysicsValidation.HEADER + validation);
        }
        GeneratedSection.write(out.resolve("accuracy-tables.md"), "accuracy-tables", tables.toString());
        GeneratedSection.write(doc, "accuracy-whitted-tables",
                "Geometric mean over the scenes (SSIM: arithmetic mean):\n\n"
                        + AccuracyReport.whittedTable(AccuracyReport.geometricMean(whitted)));
        System.out.println("wrote " + images.resolve("accuracy-*.png") + ", " + doc + " and "
                + out.resolve("accuracy-tables.md"));
    }
}
