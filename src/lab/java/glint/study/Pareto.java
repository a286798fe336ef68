package glint.study;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/** The Pareto front of (cost, error) points: those no other point beats on both. */
public final class Pareto {

    private Pareto() {
    }

    /**
     * Indices of the non-dominated points, by increasing cost. A point is dominated when another
     * has cost and error both no larger and one of them smaller.
     */
    public static List<Integer> front(double[] cost, double[] error) {
        return front(cost, error, 0);
    }

    /**
     * The front with a tolerance: going from the cheapest point up, a point joins only if its error
     * is below (1 - tolerance) times the error of the last point that joined. With tolerance 0 this
     * is the Pareto front; with 0.02, a point that costs more to gain less than 2 % is left off.
     */
    public static List<Integer> front(double[] cost, double[] error, double tolerance) {
        if (cost.length != error.length) {
            throw new IllegalArgumentException("cost and error differ in length");
        }
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < cost.length; i++) {
            order.add(i);
        }
        order.sort(Comparator.<Integer>comparingDouble(i -> cost[i]).thenComparingDouble(i -> error[i]));
        List<Integer> front = new ArrayList<>();
        double best = Double.POSITIVE_INFINITY;
        for (int i : order) {
            if (error[i] < best * (1 - tolerance) || front.isEmpty()) {
                front.add(i);
                best = error[i];
            }
        }
        return front;
    }
}
