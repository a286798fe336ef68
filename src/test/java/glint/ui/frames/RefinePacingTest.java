package glint.ui.frames;

import static org.junit.jupiter.api.Assertions.assertEquals;

import glint.config.Config;
import glint.image.FrameBuffer;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Tracer;
import glint.scenefile.SceneLoader;
import glint.ui.TestScenes;
import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/** Quick still passes are traced several in one go; their running average is the same image. */
class RefinePacingTest {

    private static final long MS = 1_000_000;

    @Test
    void aboutAnIntervalsWorthOfPassesInOneGoTheFirstAlone() {
        RefinePacing pacing = new RefinePacing();
        pacing.interval(66 * MS);
        assertEquals(1, pacing.passes(0, 64, 0), "the first image at once");
        pacing.passesDone(1, 1, 64, 0, 20 * MS, new ResolutionGovernor.Size(8, 8), null);
        assertEquals(3, pacing.passes(1, 64, 20 * MS), "20 ms a pass: 3 in 66 ms");
        pacing.passesDone(4, 3, 64, 20 * MS, 80 * MS, new ResolutionGovernor.Size(8, 8), null);
        assertEquals(3, pacing.passes(4, 64, 80 * MS));
        pacing.passesDone(7, 3, 64, 80 * MS, 80 * MS + 3 * 200 * MS, new ResolutionGovernor.Size(8, 8), null);
        assertEquals(1, pacing.passes(7, 64, 700 * MS), "slow passes: one at a time");
        pacing.passesDone(8, 1, 64, 700 * MS, 700 * MS + MS / 10, new ResolutionGovernor.Size(8, 8), null);
        assertEquals(RefinePacing.MOST_PASSES, pacing.passes(8, 64, 701 * MS), "at most 16");
        assertEquals(2, pacing.passes(62, 64, 702 * MS), "never beyond the last");
        RefinePacing none = new RefinePacing();
        none.passesDone(1, 1, 64, 0, MS, new ResolutionGovernor.Size(8, 8), null);
        assertEquals(1, none.passes(1, 64, MS), "no interval: one at a time");
        assertEquals(100 * MS, RefinePacing.windowInterval(20.0), "two frames at 20 frames a second");
    }

    @Test
    void passesInBatchesAverageToTheStillImage() throws Exception {
        RenderScene scene = RenderScene.compile(SceneLoader.parse("s.yaml", TestScenes.sphere(0.1, 0.2, 0.3)),
                Config.defaults().renderSettings());
        int w = 40, h = 30, samples = 16;
        FrameBuffer still = new FrameBuffer(w, h);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(scene, still, samples, 0, 4);
        }
        int[] expected = SrgbEncoder.pixels(stillImage(still));
        try (FrameRenderer renderer = new FrameRenderer(2, 4)) {
            BufferedImage image = null;
            int[] batches = {1, 3, 5, 7};
            for (int pass = 0, b = 0; pass < samples; pass += batches[b++]) {
                image = renderer.renderPasses(scene, w, h, samples, pass, batches[b]);
            }
            int[] got = SrgbEncoder.pixels(image);
            for (int i = 0; i < got.length; i++) {
                for (int shift = 0; shift <= 16; shift += 8) {
                    int a = got[i] >> shift & 0xff, e = expected[i] >> shift & 0xff;
                    assertEquals(e, a, 1, "pixel " + i + ": within one level of float rounding");
                }
            }
        }
    }

    private static BufferedImage stillImage(FrameBuffer frame) {
        BufferedImage image = SrgbEncoder.newImage(frame.width(), frame.height());
        SrgbEncoder.encode(frame, SrgbEncoder.pixels(image), 0, frame.width() * frame.height());
        return image;
    }
}
