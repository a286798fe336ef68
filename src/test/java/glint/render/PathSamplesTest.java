package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The path's random numbers: permutations that are bijections, and every dimension stratified. */
class PathSamplesTest {

    @Test
    void permuteIsABijectionOfEveryRange() {
        for (int n = 1; n <= 300; n++) {
            for (long seed : new long[] {0, 1, -1, 0x9E3779B97F4A7C15L, n * 31L}) {
                boolean[] seen = new boolean[n];
                for (int i = 0; i < n; i++) {
                    int image = PathSamples.permute(i, n, seed);
                    assertTrue(image >= 0 && image < n, "in range");
                    assertTrue(!seen[image], "n " + n + ": " + image + " twice");
                    seen[image] = true;
                }
            }
        }
    }

    @Test
    void thePermutationsOfTwoSeedsDiffer() {
        int same = 0;
        for (int i = 0; i < 256; i++) {
            same += PathSamples.permute(i, 256, 12345) == PathSamples.permute(i, 256, 54321) ? 1 : 0;
        }
        assertTrue(same < 16, "about one fixed point expected, got " + same);
    }

    @Test
    void aPixelsSamplesFillEveryCellOfEveryDimension() {
        PathSamples p = new PathSamples();
        int samples = 16, side = 4;
        for (int dimension = 0; dimension < 40; dimension++) {
            boolean[] cells = new boolean[samples], intervals = new boolean[samples];
            for (int sample = 0; sample < samples; sample++) {
                p.begin(1234, 5, sample, samples);
                p.pair(dimension);
                assertTrue(p.u1 >= 0 && p.u1 < 1 && p.u2 >= 0 && p.u2 < 1);
                int cell = (int) (p.u2 * side) * side + (int) (p.u1 * side);
                assertTrue(!cells[cell], "dimension " + dimension + ": cell " + cell + " twice");
                cells[cell] = true;
                double u = p.single(dimension);
                int interval = (int) (u * samples);
                assertTrue(!intervals[interval], "dimension " + dimension + ": interval " + interval + " twice");
                intervals[interval] = true;
            }
        }
    }

    @Test
    void theNumbersArePureFunctionsOfPixelFrameSampleAndDimension() {
        PathSamples a = new PathSamples(), b = new PathSamples();
        a.begin(77, 2, 3, 64);
        a.pair(6);
        b.begin(1, 1, 1, 4);
        b.pair(2);
        b.begin(77, 2, 3, 64);
        b.pair(6);
        assertEquals(a.u1, b.u1);
        assertEquals(a.u2, b.u2);
        assertEquals(a.single(9), b.single(9));
        b.begin(78, 2, 3, 64);
        b.pair(6);
        assertTrue(a.u1 != b.u1, "another pixel, other numbers");
    }
}
