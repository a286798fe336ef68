package glint.ui.frames;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** While moving, the render scale settles where frames take the target time, within [1, display_scale]. */
class ResolutionGovernorTest {

    private static final int W = 1280;
    private static final int H = 720;

    /** Render time of a frame: a fixed part plus a part per pixel. */
    private static double frameSeconds(double scale, double secondsPerPixel, double fixed) {
        int w = ResolutionGovernor.renderSize(W, scale);
        int h = ResolutionGovernor.renderSize(H, scale);
        return fixed + secondsPerPixel * w * h;
    }

    @Test
    void settlesOnTheTargetFrameRate() {
        ResolutionGovernor g = new ResolutionGovernor(30, 8);
        double perPixel = 1.0 / 30 / (W * H / 9.0); // the target is met at scale 3
        for (int i = 0; i < 30; i++) {
            g.frameTook(frameSeconds(g.scale(), perPixel, 0.002));
        }
        double t = frameSeconds(g.scale(), perPixel, 0.002);
        assertEquals(1.0 / 30, t, 0.1 / 30, "frame time at scale " + g.scale());
        assertTrue(g.scale() > 3, "the fixed cost asks for a little more: " + g.scale());
    }

    @Test
    void fastScenesRenderAtFullResolution() {
        ResolutionGovernor g = new ResolutionGovernor(30, 4);
        for (int i = 0; i < 30; i++) {
            g.frameTook(frameSeconds(g.scale(), 1e-10, 0));
        }
        assertEquals(1, g.scale());
    }

    @Test
    void displayScaleIsTheFloorOfTheResolution() {
        ResolutionGovernor g = new ResolutionGovernor(60, 2);
        assertEquals(2, g.scale(), "starts at the cheapest allowed");
        for (int i = 0; i < 30; i++) {
            g.frameTook(frameSeconds(g.scale(), 1e-6, 0)); // far too slow for 60 fps
        }
        assertEquals(2, g.scale());
    }

    @Test
    void newLimitsApplyAtOnce() {
        ResolutionGovernor g = new ResolutionGovernor(30, 8);
        g.setLimits(30, 2);
        assertEquals(2, g.scale());
        g.setLimits(30, 0.5); // never above full resolution
        assertEquals(1, g.scale());
    }

    @Test
    void noiseInsideTheDeadBandKeepsTheScale() {
        ResolutionGovernor g = new ResolutionGovernor(30, 4);
        g.frameTook(frameSeconds(g.scale(), 1.0 / 30 / (W * H / 4.0), 0));
        double settled = g.scale();
        g.frameTook(1.0 / 30 * 1.03);
        g.frameTook(1.0 / 30 * 0.97);
        assertEquals(settled, g.scale());
        g.frameTook(0); // not a measurement
        assertEquals(settled, g.scale());
    }

    @Test
    void renderSizeRoundsAndKeepsAPixel() {
        assertEquals(400, ResolutionGovernor.renderSize(800, 2));
        assertEquals(267, ResolutionGovernor.renderSize(800, 3));
        assertEquals(1, ResolutionGovernor.renderSize(3, 64));
    }
}
