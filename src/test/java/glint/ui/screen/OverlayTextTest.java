package glint.ui.screen;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.render.Shading;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The overlay's lines, and their wrapping to the window's width. */
class OverlayTextTest {

    private static final OverlayText.Tone E = OverlayText.Tone.ERROR;

    private static List<String> wrap(String text, int max) {
        return OverlayText.wrap(List.of(new OverlayText.Line(text, E)), String::length, max).stream()
                .map(OverlayText.Line::text).toList();
    }

    @Test
    void linesBreakAtSpacesAndKeepTheirTone() {
        assertEquals(List.of("scene.yaml:16:53: unknown", "  key 'colour'"), wrap("scene.yaml:16:53: unknown key 'colour'", 26));
        List<OverlayText.Line> wrapped = OverlayText.wrap(List.of(new OverlayText.Line("a b c d", E)), String::length, 3);
        assertTrue(wrapped.stream().allMatch(l -> l.tone() == E));
        assertEquals(List.of("a b", "  c", "  d"), wrapped.stream().map(OverlayText.Line::text).toList());
    }

    @Test
    void aWordTooLongForALineIsCutAnywhereAndWrappingEnds() {
        assertEquals(List.of("abcde", "  fgh", "  ijk"), wrap("abcdefghijk", 5));
        List<String> narrow = wrap("/a/very/long/path/without/spaces.yaml:1:1: bad", 1);
        assertEquals("/a/very/long/path/without/spaces.yaml:1:1: bad".replace(" ", ""),
                String.join("", narrow).replace(" ", ""));
        assertEquals(List.of("short"), wrap("short", 80));
        assertEquals(List.of(), wrap("", 80));
    }

    @Test
    void theStatsLines() {
        FrameStats moving = new FrameStats(27.14, 39.2, 400, 300, 800, 600, 1, 4, true, 2, Shading.COOK_TORRANCE, 5,
                2.0, "scenes/default.yaml", "", "", "", "");
        assertEquals(List.of("27.1 fps   39.2 ms/frame", "render 400x300 (1/2.00 of 800x600)  moving",
                "samples 1/4   threads 2", "shading cook-torrance   depth 5   speed 2/s", "scenes/default.yaml",
                "H hides this, ? shows the keys"), OverlayText.lines(moving).stream().map(OverlayText.Line::text).toList());
        FrameStats idle = new FrameStats(Double.NaN, 41.25, 800, 600, 800, 600, 4, 4, false, 2, Shading.PHONG, 3,
                2.5, "s.yaml", "saved x.png", "s.yaml:1:2: bad", "", "");
        List<OverlayText.Line> lines = OverlayText.lines(idle);
        assertEquals("idle: image complete   last frame 41.3 ms", lines.get(0).text());
        assertEquals("render 800x600 (full of 800x600)", lines.get(1).text());
        assertTrue(lines.contains(new OverlayText.Line("saved x.png", OverlayText.Tone.NOTE)));
        assertTrue(lines.contains(new OverlayText.Line("s.yaml:1:2: bad", OverlayText.Tone.ERROR)));
    }

    @Test
    void theFirstFramesOfARefinementReadRefiningNotIdle() {
        FrameStats first = new FrameStats(Double.NaN, 18.5, 800, 600, 800, 600, 1, 64, false, 2, Shading.PHONG, 3,
                2, "s.yaml", "", "", "", "");
        assertEquals("refining   last frame 18.5 ms", OverlayText.lines(first).get(0).text());
        FrameStats failed = new FrameStats(Double.NaN, 18.5, 800, 600, 800, 600, 1, 64, false, 2, Shading.PHONG, 3,
                2, "s.yaml", "", "", "", "render failed: out of memory; trying again");
        assertEquals("waiting to try again   last frame 18.5 ms", OverlayText.lines(failed).get(0).text());
    }

    @Test
    void aClampedRenderSizeAndARenderFailureAreShown() {
        FrameStats s = new FrameStats(Double.NaN, 3, 115, 86, 400, 300, 1, 1, false, 2, Shading.PHONG, 3,
                2, "s.yaml", "", "", "10,000 pixels (max_image_pixels)",
                "render failed: a render worker failed: java.lang.NullPointerException; trying again");
        List<OverlayText.Line> lines = OverlayText.lines(s);
        assertEquals("render 115x86 (1/3.48 of 400x300)", lines.get(1).text());
        assertEquals(new OverlayText.Line("window too large: rendered at most 10,000 pixels (max_image_pixels)",
                OverlayText.Tone.NOTE), lines.get(2));
        assertTrue(lines.contains(new OverlayText.Line(
                "render failed: a render worker failed: java.lang.NullPointerException; trying again",
                OverlayText.Tone.ERROR)));
    }
}
