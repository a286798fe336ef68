package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.render.TileOrder;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.IntUnaryOperator;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * The time left of a still, on a clock the test moves: a render of 8 x 8 tiles whose top rows are cheap
 * sky and whose lower rows are a costly floor with a costlier ball in the middle, as in scenes/field.yaml.
 * Handed out in the tracer's order, the estimate falls at every line; handed out row by row, it would
 * grow while the cheap rows are behind.
 */
class TimeLeftTest {

    private static final int SIDE = 8;
    private static final int TILES = SIDE * SIDE;
    private static final Pattern LEFT = Pattern.compile("rendering: (\\d+)% done, (about (\\d+) s left|time left not known yet)");

    /** Seconds a tile takes: sky 0.05, floor 0.4, the ball 1. */
    private static double cost(int tile) {
        int row = tile / SIDE, column = tile % SIDE;
        if (row < 3) {
            return 0.05;
        }
        return row <= 5 && (column == 3 || column == 4) ? 1 : 0.4;
    }

    /**
     * The seconds left of each progress line that estimates them, of a render whose i-th tile is
     * {@code order(i)}; the line of the first tenth, before any estimate, is checked and left out.
     */
    private static List<Integer> secondsLeft(IntUnaryOperator order) {
        long[] now = {0};
        int[] done = {0};
        StringWriter text = new StringWriter();
        Progress progress = Progress.onClock(new PrintWriter(text, true), () -> now[0]);
        now[0] = Progress.QUIET_NANOS; // the scene took that long to read: every line of the render shows
        progress.step("rendering", () -> done[0] / (double) TILES);
        for (int i = 0; i < TILES; i++) {
            now[0] += Math.round(cost(order.applyAsInt(i)) * 1e9);
            done[0]++;
            progress.show();
        }
        progress.close();
        List<String> lines = text.toString().lines().toList();
        assertEquals("rendering: 1% done, time left not known yet", lines.get(0));
        List<Integer> left = new ArrayList<>();
        for (String line : lines.subList(1, lines.size())) {
            Matcher m = LEFT.matcher(line);
            assertTrue(m.matches() && m.group(3) != null, line);
            left.add(Integer.parseInt(m.group(3)));
        }
        return left;
    }

    @Test
    void theTracersOrderHandsOutEveryTileOnce() {
        for (int side = 1; side <= 40; side++) {
            int tiles = side * side;
            int stride = TileOrder.stride(tiles);
            Set<Integer> seen = new HashSet<>();
            for (int i = 0; i < tiles; i++) {
                seen.add(TileOrder.tile(i, tiles, stride));
            }
            assertEquals(tiles, seen.size(), "side " + side + ", stride " + stride);
        }
    }

    @Test
    void inTheTracersOrderTheTimeLeftFallsAtEveryLine() {
        int stride = TileOrder.stride(TILES);
        List<Integer> left = secondsLeft(i -> TileOrder.tile(i, TILES, stride));
        assertEquals(9, left.size(), left::toString); // 10 % to 90 %
        for (int k = 1; k < left.size(); k++) {
            assertTrue(left.get(k) < left.get(k - 1), () -> "seconds left by tenths: " + left);
        }
    }

    @Test
    void rowByRowTheTimeLeftWouldGrowOnceTheSkyIsDone() {
        List<Integer> left = secondsLeft(i -> i);
        assertTrue(left.get(4) > 2 * left.get(2), () -> "seconds left by tenths: " + left); // 30 % sky, 50 % floor
    }
}
