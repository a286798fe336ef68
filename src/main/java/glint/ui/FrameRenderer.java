package glint.ui;

import glint.render.FrameBuffer;
import glint.render.RenderScene;
import glint.render.Tracer;
import java.awt.image.BufferedImage;

/**
 * The engine's use of the tracer: a quick one-sample frame while the camera moves, or the next
 * sample pass of the progressive still image. Each call returns a new image of a complete frame.
 */
final class FrameRenderer implements AutoCloseable {

    private Tracer tracer;
    private int divider;
    private FrameBuffer buffer;
    private final Accumulator accumulator = new Accumulator();

    FrameRenderer(int threads, int divider) {
        this.tracer = new Tracer(threads);
        this.divider = divider;
    }

    int threads() {
        return tracer.threads();
    }

    /** Uses {@code threads} render threads from now on (a new pool if the count changed). */
    void configure(int threads, int newDivider) {
        if (threads != tracer.threads()) {
            tracer.close();
            tracer = new Tracer(threads);
        }
        divider = newDivider;
    }

    /** A frame with one sample per pixel, through the pixel centres. */
    BufferedImage renderMoving(RenderScene scene, int width, int height) {
        FrameBuffer frame = buffer(width, height);
        tracer.render(scene, frame, 1, 0, divider);
        return SrgbEncoder.toImage(frame);
    }

    /**
     * Pass {@code pass} of the still image of {@code samples} samples per pixel, averaged with the
     * passes before it (pass 0 starts over).
     */
    BufferedImage renderPass(RenderScene scene, int width, int height, int samples, int pass) {
        if (pass == 0) {
            accumulator.reset(width, height);
        }
        FrameBuffer frame = buffer(width, height);
        tracer.renderPass(scene, frame, samples, pass, divider);
        return SrgbEncoder.toImage(accumulator.add(frame));
    }

    private FrameBuffer buffer(int width, int height) {
        if (buffer == null || buffer.width() != width || buffer.height() != height) {
            buffer = new FrameBuffer(width, height);
        }
        return buffer;
    }

    @Override
    public void close() {
        tracer.close();
    }
}
