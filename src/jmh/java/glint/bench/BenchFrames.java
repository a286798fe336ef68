package glint.bench;

import glint.image.FrameBuffer;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Tracer;
import glint.scene.Scene;

/**
 * What the frame benchmarks render with: a compiled scene, an 800x600 frame and a tracer, one
 * sample per pixel in 8 x 8 tiles, with the settings given ({@link BenchScenes#SETTINGS} or a variant).
 */
final class BenchFrames implements AutoCloseable {

    private final RenderScene scene;
    private final FrameBuffer frame = new FrameBuffer(800, 600);
    private final Tracer tracer;

    BenchFrames(Scene scene, RenderSettings settings, int threads) {
        this.scene = RenderScene.compile(scene, settings);
        this.tracer = new Tracer(threads);
    }

    /** Renders one frame; the frame is returned so that JMH keeps the work. */
    FrameBuffer render() {
        tracer.render(scene, frame, 1, 0, 8);
        return frame;
    }

    @Override
    public void close() {
        tracer.close();
    }
}
