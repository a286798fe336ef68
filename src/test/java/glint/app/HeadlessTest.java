package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The per-frame line of {@code --bench}. */
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
}
