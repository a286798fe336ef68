package glint.ui;

import glint.image.FrameBuffer;
import glint.render.RenderScene;
import glint.render.Tracer;
import glint.ui.frames.FrameRenderer;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The tracer with faults on demand: while {@link #faults} is above 0, each frame fails (every render worker
 * throws in its tile, or {@link #error} is thrown) and counts it down; {@link #calls} counts every frame.
 */
public final class FaultyTrace implements FrameRenderer.TraceCall {

    public final AtomicInteger calls = new AtomicInteger();
    public final AtomicInteger faults = new AtomicInteger();
    public volatile Error error;

    @Override
    public void trace(Tracer tracer, RenderScene scene, FrameBuffer target, int samples, int pass, int count,
                      int divider) {
        calls.incrementAndGet();
        if (faults.getAndUpdate(n -> Math.max(0, n - 1)) > 0) {
            if (error != null) {
                throw error;
            }
            TRACER.trace(tracer, null, target, samples, pass, count, divider); // every worker throws in its tile
        }
        TRACER.trace(tracer, scene, target, samples, pass, count, divider);
    }
}
