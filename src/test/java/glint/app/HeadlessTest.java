package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The per-frame line of {@code --bench}, the progress shown (the memory check: {@code glint.still.MemoryCheckTest}). */
class HeadlessTest {

    @Test
    void aFrameLineGivesTheWallClockThenTheRenderThreadsCpuTime() {
        assertEquals("frame 3: 41.53 ms, render cpu 80.12 ms",
                Headless.frameLine(3, 41.534, 5_080_120_000L, 5_000_000_000L));
    }

    @Test
    void withoutThreadCpuClocksTheLineGivesTheWallClockAlone() {
        assertEquals("frame 1: 9.00 ms", Headless.frameLine(1, 9.0, -1, -1));
    }

    // ---------------------------------------------------------------- progress

    @Test
    void progressLinesGivePercentDoneAndTheTimeLeftAtTheSameSpeed() {
        // a quarter in 10 s: three quarters take 30 s more
        assertEquals("rendering: 25% done, about 30 s left", Progress.line(0.25, 10_000_000_000L));
        // a tenth in 25 s: 225 s = 3 min 45 s more
        assertEquals("rendering: 10% done, about 3 min 45 s left", Progress.line(0.1, 25_000_000_000L));
        // 12 % in 15 min: 6,600 s = 1 h 50 min more
        assertEquals("rendering: 12% done, about 1 h 50 min left", Progress.line(0.12, 900_000_000_000L));
        // under a tenth the pace of the first tiles says too little
        assertEquals("rendering: 9% done, time left not known yet", Progress.line(0.09, 60_000_000_000L));
        assertEquals("rendering: 0% done, time left not known yet", Progress.line(0, 3_000_000_000L));
    }

    @Test
    void everyStepThatKnowsHowFarItIsHasTheSameLine() {
        assertEquals("writing the image: 50% done, about 3 s left", Progress.line("writing the image", 0.5, 3_000_000_000L));
    }

    /**
     * Plain lines on a clock the test moves: nothing for 2 s, each step as it begins, a line at every
     * further tenth, and one at least every 10 s while nothing changes (a stretch of slow tiles, a
     * long compile), so that a log never falls silent.
     */
    @Test
    void aStepShowsItselfAtEveryTenthAndAtLeastEveryTenSeconds() {
        long[] now = {0};
        double[] done = {0};
        java.io.StringWriter text = new java.io.StringWriter();
        Progress progress = Progress.onClock(new java.io.PrintWriter(text, true), () -> now[0]);
        progress.step("preparing the scene", null);
        at(progress, now, 1.0);             // quiet for the first 2 s
        at(progress, now, 2.5);             // preparing the scene...
        at(progress, now, 8.0);
        at(progress, now, 12.5);            // preparing the scene... 12 s so far
        progress.step("rendering", () -> done[0]);
        done[0] = 0.05;
        at(progress, now, 13.0);            // rendering: 5% done
        done[0] = 0.06;
        at(progress, now, 18.0);            // no new tenth, not 10 s yet
        at(progress, now, 23.0);            // 10 s since the last line
        done[0] = 0.12;
        at(progress, now, 24.0);            // a new tenth
        done[0] = 1;
        at(progress, now, 40.0);            // done: the step's end is the report line, not a progress line
        progress.close();
        assertEquals(java.util.List.of("preparing the scene...", "preparing the scene... 12 s so far",
                "rendering: 5% done, time left not known yet", "rendering: 6% done, time left not known yet",
                "rendering: 12% done, about 1 min 24 s left"), text.toString().lines().toList());
    }

    private static void at(Progress progress, long[] now, double seconds) {
        now[0] = (long) (seconds * 1e9);
        progress.show();
    }

    @Test
    void theBarFillsInProportion() {
        // 30 cells, half of them filled
        assertEquals("[###############               ]  50%, about 4 s left", Progress.bar(0.5, 4_000_000_000L));
    }
}
