package glint.study;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.ToDoubleFunction;

/** The markdown tables of the speed/accuracy study, and the verdict drawn from each scene's front. */
final class AccuracyReport {

    private AccuracyReport() {
    }

    /**
     * The methods of one scene against physics, by render CPU: the four errors and whether the method
     * is on the front of relMSE and of FLIP.
     */
    static String methodsTable(List<Measurement> ms) {
        Set<Integer> onRelMse = new HashSet<>(front(ms, Measurement::relMse));
        Set<Integer> onFlip = new HashSet<>(front(ms, Measurement::flip));
        StringBuilder b = new StringBuilder();
        b.append("| method | render CPU ms | relMSE | SSIM | FLIP | 8-bit error | front: relMSE | front: FLIP |\n");
        b.append("|---|--:|--:|--:|--:|--:|:-:|:-:|\n");
        for (int i : byCpu(ms)) {
            Measurement m = ms.get(i);
            b.append("| ").append(name(m.config(), m.config().methodLabel()))
                    .append(" | ").append(Numbers.fixed(m.cpuMillis(), 1))
                    .append(" | ").append(Numbers.sig3(m.relMse()))
                    .append(" | ").append(Numbers.fixed(m.ssim(), 4))
                    .append(" | ").append(Numbers.fixed(m.flip(), 4))
                    .append(" | ").append(Numbers.fixed(m.errors().levels(), 2))
                    .append(" | ").append(onRelMse.contains(i) ? "yes" : "")
                    .append(" | ").append(onFlip.contains(i) ? "yes" : "")
                    .append(" |\n");
        }
        return b.toString();
    }

    /**
     * Whitted's configurations against its own converged image, by render CPU, with their ratios to
     * the shipped default and marks for the front (on CPU time and relMSE, 2 % tolerance).
     */
    static String whittedTable(List<Measurement> ms) {
        Set<Integer> front = new HashSet<>(front(ms, Measurement::relMse));
        StudyConfig shipped = StudyConfig.shipped();
        double shippedCpu = Double.NaN, shippedErr = Double.NaN;
        for (Measurement m : ms) {
            if (m.config().equals(shipped)) {
                shippedCpu = m.cpuMillis();
                shippedErr = m.relMse();
            }
        }
        StringBuilder b = new StringBuilder();
        b.append("| configuration | render CPU ms | relMSE | SSIM | CPU / shipped | relMSE / shipped | on the front |\n");
        b.append("|---|--:|--:|--:|--:|--:|:-:|\n");
        for (int i : byCpu(ms)) {
            Measurement m = ms.get(i);
            b.append("| ").append(name(m.config(), m.config().label()))
                    .append(" | ").append(Numbers.fixed(m.cpuMillis(), 1))
                    .append(" | ").append(Numbers.sig3(m.relMse()))
                    .append(" | ").append(Numbers.fixed(m.ssim(), 4))
                    .append(" | ").append(Numbers.fixed(m.cpuMillis() / shippedCpu, 2))
                    .append(" | ").append(Numbers.fixed(m.relMse() / shippedErr, 2))
                    .append(" | ").append(front.contains(i) ? "yes" : "")
                    .append(" |\n");
        }
        return b.toString();
    }

    /** What one scene's front says: Whitted's best, where the path tracer takes the front over, on two errors. */
    record Verdict(String scene, Measurement bestWhitted, Measurement pathMatching, Measurement pathWinsRelMse,
                   Measurement pathWinsFlip) {
    }

    /** The verdict between Whitted and the path tracer; the bidirectional tracer's points are left out of it. */
    static Verdict verdict(String scene, List<Measurement> all) {
        List<Measurement> ms = all.stream().filter(m -> m.config().method() != StudyConfig.Method.BDPT).toList();
        Measurement best = null;
        for (Measurement m : ms) {
            if (!m.config().isPath() && (best == null || m.relMse() < best.relMse())) {
                best = m;
            }
        }
        Measurement matching = null;
        for (Measurement m : ms) {
            if (m.config().isPath() && best != null && m.relMse() <= best.relMse()
                    && (matching == null || m.cpuMillis() < matching.cpuMillis())) {
                matching = m;
            }
        }
        return new Verdict(scene, best, matching, pathTakesOver(ms, Measurement::relMse),
                pathTakesOver(ms, Measurement::flip));
    }

    /**
     * The front's point from which on every point of it is the path tracer's: the budget from which
     * the path wins; null if the front's most expensive point is not the path's.
     */
    static Measurement pathTakesOver(List<Measurement> ms, ToDoubleFunction<Measurement> error) {
        List<Integer> front = front(ms, error);
        Measurement from = null;
        for (int i : front) {
            Measurement m = ms.get(i);
            if (!m.config().isPath()) {
                from = null;
            } else if (from == null) {
                from = m;
            }
        }
        return from;
    }

    /** The verdicts as a table, one row a scene. */
    static String verdictTable(List<Verdict> verdicts) {
        StringBuilder b = new StringBuilder();
        b.append("| scene | Whitted's best: method, render CPU | its relMSE / FLIP | path wins on relMSE from | "
                + "path wins on FLIP from | path at least as good as Whitted's best (relMSE) |\n");
        b.append("|---|---|--:|---|---|---|\n");
        for (Verdict v : verdicts) {
            b.append("| ").append(v.scene())
                    .append(" | ").append(at(v.bestWhitted()))
                    .append(" | ").append(Numbers.sig3(v.bestWhitted().relMse())).append(" / ")
                    .append(Numbers.fixed(v.bestWhitted().flip(), 3))
                    .append(" | ").append(at(v.pathWinsRelMse()))
                    .append(" | ").append(at(v.pathWinsFlip()))
                    .append(" | ").append(at(v.pathMatching()))
                    .append(" |\n");
        }
        return b.toString();
    }

    private static String at(Measurement m) {
        return m == null ? "not up to path s1024" : m.config().methodLabel() + ", " + Numbers.fixed(m.cpuMillis(), 0) + " ms";
    }

    /** Per configuration, the geometric mean over scenes of time and relMSE and the mean of the other errors. */
    static List<Measurement> geometricMean(List<List<Measurement>> perScene) {
        List<Measurement> out = new ArrayList<>();
        int configs = perScene.get(0).size();
        for (int c = 0; c < configs; c++) {
            double logMs = 0, logCpu = 0, logErr = 0, ssim = 0, flip = 0, levels = 0;
            for (List<Measurement> scene : perScene) {
                Measurement m = scene.get(c);
                logMs += Math.log(m.millis());
                logCpu += Math.log(m.cpuMillis());
                logErr += Math.log(m.relMse());
                ssim += m.ssim();
                flip += m.flip();
                levels += m.errors().levels();
            }
            int n = perScene.size();
            out.add(new Measurement("geometric mean", perScene.get(0).get(c).config(), Math.exp(logMs / n),
                    Math.exp(logCpu / n), new ImageErrors(Math.exp(logErr / n), ssim / n, flip / n, levels / n)));
        }
        return out;
    }

    private static List<Integer> front(List<Measurement> ms, ToDoubleFunction<Measurement> error) {
        double[] x = new double[ms.size()], y = new double[ms.size()];
        for (int i = 0; i < ms.size(); i++) {
            x[i] = ms.get(i).cpuMillis();
            y[i] = error.applyAsDouble(ms.get(i));
        }
        return Pareto.front(x, y, AccuracyChart.FRONT_TOLERANCE);
    }

    private static List<Integer> byCpu(List<Measurement> ms) {
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < ms.size(); i++) {
            order.add(i);
        }
        order.sort((a, b) -> Double.compare(ms.get(a).cpuMillis(), ms.get(b).cpuMillis()));
        return order;
    }

    private static String name(StudyConfig config, String label) {
        return config.equals(StudyConfig.shipped()) ? "**" + label + "** (shipped)" : label;
    }
}
