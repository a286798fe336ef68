package glint.shading;

/**
 * Multiple importance sampling (Veach 1997, ch. 9): where two strategies can find the same light,
 * a BSDF sample and a light sample, each weighs what it finds by the power heuristic, so that the
 * two weights of a path sum to 1 and each strategy counts most where its density is the larger.
 */
public final class Mis {

    private Mis() {
    }

    /**
     * The power heuristic's weight (beta = 2) of a sample of density {@code pdf} against the other
     * strategy's density {@code otherPdf} for the same direction: pdf^2 / (pdf^2 + otherPdf^2); 1
     * where the other strategy cannot find it.
     */
    public static double powerHeuristic(double pdf, double otherPdf) {
        if (!(otherPdf > 0)) {
            return 1;
        }
        if (!(pdf > 0)) {
            return 0;
        }
        double ratio = otherPdf / pdf; // a ratio first: squares of densities of narrow lobes would overflow
        return 1 / (1 + ratio * ratio);
    }
}
