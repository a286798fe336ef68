package glint.study;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/** The markdown tables of the speed/accuracy study. */
final class AccuracyReport {

    private AccuracyReport() {
    }

    /**
     * One table: configurations by CPU time, with wall time, relMSE, SSIM, and marks for the front
     * (on CPU time and relMSE, 2 % tolerance) and the shipped default.
     */
    static String table(List<Measurement> ms) {
        double[] x = new double[ms.size()], y = new double[ms.size()];
        for (int i = 0; i < ms.size(); i++) {
            x[i] = ms.get(i).cpuMillis();
            y[i] = ms.get(i).relMse();
        }
        Set<Integer> front = new HashSet<>(Pareto.front(x, y, AccuracyChart.FRONT_TOLERANCE));
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < ms.size(); i++) {
            order.add(i);
        }
        order.sort((a, b) -> Double.compare(x[a], x[b]));
        StringBuilder b = new StringBuilder();
        StudyConfig shipped = StudyConfig.shipped();
        double shippedCpu = Double.NaN, shippedErr = Double.NaN;
        for (Measurement m : ms) {
            if (m.config().equals(shipped)) {
                shippedCpu = m.cpuMillis();
                shippedErr = m.relMse();
            }
        }
        b.append("| configuration | CPU ms | wall ms | relMSE | SSIM | CPU / shipped | relMSE / shipped | on the front |\n");
        b.append("|---|--:|--:|--:|--:|--:|--:|:-:|\n");
        for (int i : order) {
            Measurement m = ms.get(i);
            String name = m.config().equals(shipped) ? "**" + m.config().label() + "** (shipped)" : m.config().label();
            b.append("| ").append(name)
                    .append(" | ").append(Numbers.fixed(m.cpuMillis(), 1))
                    .append(" | ").append(Numbers.fixed(m.millis(), 1))
                    .append(" | ").append(Numbers.sig3(m.relMse()))
                    .append(" | ").append(Numbers.fixed(m.ssim(), 4))
                    .append(" | ").append(Numbers.fixed(m.cpuMillis() / shippedCpu, 2))
                    .append(" | ").append(Numbers.fixed(m.relMse() / shippedErr, 2))
                    .append(" | ").append(front.contains(i) ? "yes" : "")
                    .append(" |\n");
        }
        return b.toString();
    }

    /** Per configuration, the geometric mean over scenes of time and relMSE and the mean SSIM. */
    static List<Measurement> geometricMean(List<List<Measurement>> perScene) {
        List<Measurement> out = new ArrayList<>();
        int configs = perScene.get(0).size();
        for (int c = 0; c < configs; c++) {
            double logMs = 0, logCpu = 0, logErr = 0, ssim = 0;
            for (List<Measurement> scene : perScene) {
                Measurement m = scene.get(c);
                logMs += Math.log(m.millis());
                logCpu += Math.log(m.cpuMillis());
                logErr += Math.log(m.relMse());
                ssim += m.ssim();
            }
            int n = perScene.size();
            out.add(new Measurement("geometric mean", perScene.get(0).get(c).config(), Math.exp(logMs / n),
                    Math.exp(logCpu / n), Math.exp(logErr / n), ssim / n));
        }
        return out;
    }
}
