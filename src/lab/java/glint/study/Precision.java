package glint.study;

/**
 * Arithmetic precision of a study model. Float arithmetic is emulated exactly by rounding each
 * double result to float: for +, -, x, / and sqrt, double has more than 2 x 24 + 2 bits, so rounding
 * the double result again to float gives the correctly rounded float result.
 */
public enum Precision {
    FLOAT, DOUBLE;

    /** The value rounded to this precision. */
    public double round(double v) {
        return this == FLOAT ? (float) v : v;
    }
}
