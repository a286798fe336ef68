package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import glint.config.Config;
import glint.input.InputException;
import org.junit.jupiter.api.Test;

/** The per-frame line of {@code --bench}, the memory check before a render, the progress shown. */
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

    // ---------------------------------------------------------------- memory

    @Test
    void theMemoryARenderNeedsIsItsFrameAndItsThreadsRowBuffers() {
        Config c = Config.defaults().withSize(1920, 1080).withSamples(4096).withThreads(2);
        // tiles 1920 / 8 = 240 pixels wide, x 4096 samples = 983,040 rays a row, x 64 bytes x 2 threads
        // = 125,829,120; the frame and image: 1920 x 1080 x 16 = 33,177,600
        assertEquals(125_829_120L + 33_177_600L, Headless.memoryNeeded(c, 16));
    }

    @Test
    void aRenderTheHeapCannotHoldIsRefusedBeforeAnyMemoryIsTaken() {
        Config c = Config.defaults().withSize(1920, 1080).withSamples(4096).withThreads(2);
        InputException e = assertThrows(InputException.class, () -> Headless.checkMemory(c, 16, 128L << 20));
        // 159,006,720 bytes round up to 152 MB; 128 MB less the 32 MB kept free
        assertEquals("glint: 1920x1080 at 4096 samples with 2 threads needs about 152 MB of memory; the Java heap "
                + "has 96 MB free (render fewer pixels, samples or threads, or start Java with a larger -Xmx)",
                e.getMessage());
    }

    @Test
    void theLargestImageAllowedFitsTheSizeArithmetic() throws InputException {
        // 26,457 x 26,457 = 699,972,849 pixels, under max_image_pixels' ceiling of 700,000,000: no int overflows
        Config c = Config.defaults().withSize(26_457, 26_457).withSamples(1).withThreads(1);
        assertEquals(699_972_849L * 16 + 3_308L * 64, Headless.memoryNeeded(c, 16));
        Headless.checkMemory(c, 16, 1L << 40); // a terabyte of heap: allowed
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
