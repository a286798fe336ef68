package glint.render;

/**
 * Where a sphere lands on a plane at distance 1 from a point of view: the range of one screen
 * coordinate over it, between the two planes through the point that touch the sphere. Widened so
 * that rounding never leaves a ray that meets the sphere outside it.
 */
final class ScreenRange {

    /**
     * Widening of a range, relative to its size: far above the rounding of the range, of a ray's
     * direction and of the sphere test (all near 1e-16), so a ray outside the widened range
     * certainly misses; far below a pixel, so it culls nearly as much as the range.
     */
    static final double MARGIN = 1e-6;

    private ScreenRange() {
    }

    /**
     * Writes to out[at], out[at + 1] the range of screen coordinate a / z over a sphere of radius r
     * whose centre is at (a, z) in a plane through the point of view (a across, z along the view),
     * widened by the margin; the whole line when the sphere is not wholly in front of the point.
     * The ends are the planes through the point tangent to the sphere: |a - s z| = r sqrt(1 + s^2).
     */
    static void of(double a, double z, double r, double[] out, int at) {
        double denominator = z * z - r * r;
        if (!(z > r) || !(denominator > 0)) {
            out[at] = Double.NEGATIVE_INFINITY;
            out[at + 1] = Double.POSITIVE_INFINITY;
            return;
        }
        double root = r * Math.sqrt(a * a + denominator);
        double low = (a * z - root) / denominator, high = (a * z + root) / denominator;
        double margin = MARGIN * (1 + Math.abs(low) + Math.abs(high));
        out[at] = low - margin;
        out[at + 1] = high + margin;
    }
}
