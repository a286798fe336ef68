package glint.study;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The camera's quaternion after a million turns. Each product of unit quaternions changes |q| by a
 * relative error of a few units in the last place u, so after n turns |q| - 1 is bounded by about
 * 8 n u (a random walk makes it ~sqrt(n) u); re-normalising each turn keeps it within a few u.
 */
class QuaternionDriftTest {

    private static final double U_DOUBLE = Math.ulp(1.0) / 2, U_FLOAT = Math.ulp(1.0f) / 2;
    private static final long[] TURNS = {1000, 1_000_000};

    @Test
    void doubleWithoutRenormalisingStaysWithinItsRoundingBound() {
        double[] e = QuaternionDrift.normError(TURNS, Precision.DOUBLE, false);
        for (int i = 0; i < TURNS.length; i++) {
            assertTrue(Math.abs(e[i]) <= 8 * TURNS[i] * U_DOUBLE, "drift " + e[i] + " after " + TURNS[i]);
        }
        assertTrue(Math.abs(e[1]) < 1e-12, "a million turns in double: negligible drift " + e[1]);
    }

    @Test
    void renormalisingKeepsTheNormWithinAFewUnitsInTheLastPlace() {
        double[] d = QuaternionDrift.normError(TURNS, Precision.DOUBLE, true);
        double[] f = QuaternionDrift.normError(TURNS, Precision.FLOAT, true);
        for (int i = 0; i < TURNS.length; i++) {
            assertTrue(Math.abs(d[i]) <= 4 * U_DOUBLE, "double " + d[i]);
            assertTrue(Math.abs(f[i]) <= 4 * U_FLOAT, "float " + f[i]);
        }
    }

    @Test
    void floatWithoutRenormalisingDriftsFarBeyondItsRenormalisedSelf() {
        // a random walk of 1e6 steps of ~u_float gives ~1e3 x 6e-8 = 6e-5; 4 u_float is 2.4e-7
        double[] f = QuaternionDrift.normError(TURNS, Precision.FLOAT, false);
        assertTrue(Math.abs(f[1]) > 100 * 4 * U_FLOAT, "float drift after a million turns: " + f[1]);
    }
}
