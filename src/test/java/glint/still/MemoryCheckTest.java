package glint.still;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import glint.config.Config;
import glint.render.LightTransport;
import org.junit.jupiter.api.Test;

/**
 * The memory check before a still (and {@code --bench}): the frame, the image and every thread's row
 * buffers against the free heap, refused in words before any memory is taken. The command line prints
 * the problem after {@code glint: }, the window after {@code still not written: }.
 */
class MemoryCheckTest {

    @Test
    void theMemoryARenderNeedsIsItsFrameAndItsThreadsRowBuffers() {
        Config c = Config.defaults().withSize(1920, 1080).withSamples(4096).withThreads(2);
        // tiles 1920 / 8 = 240 pixels wide, x 4096 samples = 983,040 rays a row, x 64 bytes x 2 threads
        // = 125,829,120; the frame and image: 1920 x 1080 x 16 = 33,177,600
        assertEquals(125_829_120L + 33_177_600L, MemoryCheck.memoryNeeded(c, 16));
    }

    @Test
    void aRenderTheHeapCannotHoldIsRefusedBeforeAnyMemoryIsTaken() {
        Config c = Config.defaults().withSize(1920, 1080).withSamples(4096).withThreads(2);
        StillRefused e = assertThrows(StillRefused.class, () -> MemoryCheck.check(c, 16, 128L << 20));
        // 159,006,720 bytes round up to 152 MB; 128 MB less the 32 MB kept free
        assertEquals("1920x1080 at 4096 samples with 2 threads needs about 152 MB of memory; the Java heap "
                + "has 96 MB free (render fewer pixels, samples or threads, or start Java with a larger -Xmx)",
                e.problem());
    }

    @Test
    void aShortfallOfLessThanAMegabyteIsShownInBytes() {
        Config c = Config.defaults().withSize(1920, 1080).withSamples(4096).withThreads(2);
        // 159,006,720 bytes needed, 100,000 fewer free (with the 32 MB kept aside): both would read 152 MB
        long free = 159_006_720L - 100_000 + (32L << 20);
        StillRefused e = assertThrows(StillRefused.class, () -> MemoryCheck.check(c, 16, free));
        assertEquals("1920x1080 at 4096 samples with 2 threads needs about 159,006,720 bytes of memory; the Java "
                + "heap has 158,906,720 bytes free (render fewer pixels, samples or threads, or start Java with a larger "
                + "-Xmx)", e.problem());
    }

    @Test
    void theLargestImageAllowedFitsTheSizeArithmetic() throws StillRefused {
        // 26,457 x 26,457 = 699,972,849 pixels, under max_image_pixels' ceiling of 700,000,000: no int overflows
        Config c = Config.defaults().withSize(26_457, 26_457).withSamples(1).withThreads(1);
        assertEquals(699_972_849L * 16 + 3_308L * 64, MemoryCheck.memoryNeeded(c, 16));
        MemoryCheck.check(c, 16, 1L << 40); // a terabyte of heap: allowed
    }

    @Test
    void aRefusalOfMemoryIsNotAboutTheOutputFile() {
        Config c = Config.defaults().withSize(1920, 1080).withSamples(4096).withThreads(2);
        assertFalse(assertThrows(StillRefused.class, () -> MemoryCheck.check(c, 16, 0)).aboutOutput());
    }

    @Test
    void aBidirectionalRenderAlsoNeedsItsPassImagesAndSplatsAPixel() {
        Config whitted = Config.defaults().withSize(800, 600).withSamples(4).withThreads(2);
        Config bdpt = whitted.withTransport(LightTransport.BDPT);
        // a pass's own image (3 floats), the sum of the passes (3 doubles), the splats (3 longs)
        assertEquals(800L * 600 * (12 + 24 + 24), MemoryCheck.memoryNeeded(bdpt, 16) - MemoryCheck.memoryNeeded(whitted, 16));
        assertEquals(MemoryCheck.memoryNeeded(whitted, 16),
                MemoryCheck.memoryNeeded(whitted.withTransport(LightTransport.PATH), 16));
    }
}
