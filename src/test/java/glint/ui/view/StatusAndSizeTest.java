package glint.ui.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Limits;
import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;

/** The overlay's status line and the window's frame size budget. */
class StatusAndSizeTest {

    private final StringWriter errText = new StringWriter();
    private final PrintWriter err = new PrintWriter(errText, true);
    private final StatusLine status = new StatusLine(err);

    @Test
    void aNewErrorIsPrintedOnceAndEveryChangeWaitsForTheOverlay() {
        assertFalse(status.isChanged());
        status.error("a.yaml:1:2: broken");
        status.error("a.yaml:1:2: broken");
        assertEquals("a.yaml:1:2: broken" + System.lineSeparator(), errText.toString());
        assertTrue(status.isChanged());
        status.shown();
        assertFalse(status.isChanged());
        status.error("");
        assertEquals("", status.error());
        assertTrue(status.isChanged());
        status.shown();
        status.note("level");
        assertEquals("level", status.message());
        assertTrue(status.isChanged());
        status.shown();
        status.changed();
        assertTrue(status.isChanged());
    }

    @Test
    void aWindowOverTheBudgetIsRenderedSmallerAndSaysSoOnce() {
        Limits limits = new Limits(10_000, Limits.DEFAULT.maxSceneBytes(), Limits.DEFAULT.maxObjects(),
                Limits.DEFAULT.maxLights(), Limits.DEFAULT.maxRecursion());
        FrameSize size = new FrameSize(100, 50, status, err);
        size.check(limits);
        assertEquals("", size.sizeLimit());
        assertEquals(100, size.fit(1).width());
        assertEquals("", errText.toString());

        assertFalse(size.resize(100, 50));
        assertTrue(size.resize(400, 200));
        size.check(limits);
        assertEquals("10,000 pixels (max_image_pixels)", size.sizeLimit());
        assertTrue(size.fit(1).width() * (long) size.fit(1).height() <= 10_000);
        assertTrue(status.message().startsWith("the window is 400x200; frames are rendered at "), status.message());
        assertTrue(size.resize(800, 400));
        size.check(limits);
        assertEquals(1, errText.toString().lines().count(), "said once while it binds: " + errText);

        assertTrue(size.resize(50, 50));
        size.check(limits);
        assertEquals("", size.sizeLimit());
        assertEquals(50, size.width());
        assertEquals(50, size.height());
    }

    @Test
    void theFrameBudgetIsAlsoWhatHalfTheHeapHolds() {
        long gigabyte = 1L << 30;
        assertEquals(Limits.DEFAULT.maxImagePixels(), FrameBudget.of(Limits.DEFAULT, 64 * gigabyte).pixels());
        assertEquals(gigabyte / 2 / FrameBudget.BYTES_PER_PIXEL, FrameBudget.of(Limits.DEFAULT, gigabyte).pixels());
        assertEquals("6,710,886 pixels (half the Java heap, -Xmx)", FrameBudget.of(Limits.DEFAULT, gigabyte).why());
        assertEquals("33,177,600 pixels (max_image_pixels)", FrameBudget.of(Limits.DEFAULT, 64 * gigabyte).why());
    }
}
