package glint.study;

import java.util.EnumMap;
import java.util.Map;

/**
 * Runs the four {@link SphereMethod}s over every pixel of a {@link SphereView} and judges each
 * against {@link ExactSphere}, computed from exactly the inputs the method saw (double inputs for
 * the double methods, the same values rounded to float for the float ones). So the study measures
 * each formula's own rounding, not the rounding of its inputs.
 */
public final class SphereStudy {

    private SphereStudy() {
    }

    public static Map<SphereMethod, SphereErrors> run(SphereView view, SphereMethod... methods) {
        Map<SphereMethod, int[]> counts = new EnumMap<>(SphereMethod.class);
        for (SphereMethod m : methods) {
            counts.put(m, new int[2]);
        }
        for (int y = 0; y < view.n(); y++) {
            for (int x = 0; x < view.n(); x++) {
                double[] d = view.direction(x, y);
                double exactDouble = Double.NaN, exactFloat = Double.NaN;
                for (SphereMethod m : methods) {
                    double cx = m.input(view.center().x()), cy = m.input(view.center().y());
                    double cz = m.input(view.center().z()), r = m.input(view.radius());
                    double ox = m.input(view.eye().x()), oy = m.input(view.eye().y()), oz = m.input(view.eye().z());
                    double dx = m.input(d[0]), dy = m.input(d[1]), dz = m.input(d[2]);
                    double exact;
                    if (m.isFloat()) {
                        if (Double.isNaN(exactFloat)) {
                            exactFloat = ExactSphere.nearestT(cx, cy, cz, r, ox, oy, oz, dx, dy, dz);
                        }
                        exact = exactFloat;
                    } else {
                        if (Double.isNaN(exactDouble)) {
                            exactDouble = ExactSphere.nearestT(cx, cy, cz, r, ox, oy, oz, dx, dy, dz);
                        }
                        exact = exactDouble;
                    }
                    double t = m.nearestT(cx, cy, cz, r, ox, oy, oz, dx, dy, dz);
                    judge(counts.get(m), exact, t, view.radius());
                }
            }
        }
        Map<SphereMethod, SphereErrors> result = new EnumMap<>(SphereMethod.class);
        int pixels = view.n() * view.n();
        counts.forEach((m, c) -> result.put(m, new SphereErrors(pixels, c[0], c[1])));
        return result;
    }

    public static Map<SphereMethod, SphereErrors> run(SphereView view) {
        return run(view, SphereMethod.values());
    }

    private static void judge(int[] counts, double exact, double t, double radius) {
        boolean exactHit = exact < Double.POSITIVE_INFINITY;
        boolean hit = t < Double.POSITIVE_INFINITY; // NaN counts as a miss
        if (exactHit != hit) {
            counts[0]++;
        } else if (hit && !(Math.abs(t - exact) <= SphereView.DISTANCE_TOLERANCE * Math.min(radius, exact))) {
            counts[1]++;
        }
    }
}
