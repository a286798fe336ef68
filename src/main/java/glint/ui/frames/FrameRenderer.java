package glint.ui.frames;

import glint.image.FrameBuffer;
import glint.image.ViewTransform;
import glint.render.RenderScene;
import glint.render.Tracer;
import java.awt.image.BufferedImage;

/**
 * The engine's use of the tracer: a quick one-sample frame while the camera moves, or the next
 * sample pass of the progressive still image. Each call returns a new image of a complete frame.
 *
 * <p>After the render threads have traced a pass, adding it to the average and encoding the average
 * to sRGB is split among as many threads as render ({@link PixelRanges}), so that a still pass in the
 * window costs little more than the same pass headless.
 */
public final class FrameRenderer implements AutoCloseable {

    /**
     * How a frame is traced: by the tracer (the window), or by a test's stand-in around it that injects a
     * fault into a tile or stamps each frame (the fault and soak tests).
     */
    @FunctionalInterface
    public interface TraceCall {

        /** What {@code pass} is for a moving frame: every sample of the pixel in one go. */
        int WHOLE_FRAME = -1;

        /** The tracer itself. */
        TraceCall TRACER = (tracer, scene, target, samples, pass, count, divider) -> {
            if (pass == WHOLE_FRAME) {
                tracer.render(scene, target, samples, 0, divider);
            } else if (count == 1) {
                tracer.renderPass(scene, target, samples, pass, divider);
            } else {
                tracer.renderPasses(scene, target, samples, pass, count, divider);
            }
        };

        /**
         * Renders into {@code target}: samples {@code pass} .. {@code pass + count - 1} of {@code samples} of
         * every pixel (their average), or all of them when {@code pass} is {@link #WHOLE_FRAME}; returns when
         * every pixel is written.
         */
        void trace(Tracer tracer, RenderScene scene, FrameBuffer target, int samples, int pass, int count,
                   int divider);
    }

    private final TraceCall call;
    private Tracer tracer;
    private int divider;
    private FrameBuffer buffer;
    private final Accumulator accumulator = new Accumulator();
    private PixelRanges ranges;
    private ViewTransform view = ViewTransform.STANDARD; // the engine sets the view's before each frame
    private boolean lastMoving = true; // what the last frame was: a moving one (in buffer) or the still's average
    private boolean anyFrame;

    public FrameRenderer(int threads, int divider) {
        this(threads, divider, TraceCall.TRACER);
    }

    public FrameRenderer(int threads, int divider, TraceCall call) {
        this.call = call;
        this.tracer = new Tracer(threads);
        this.ranges = new PixelRanges(threads);
        this.divider = divider;
    }

    public int threads() {
        return tracer.threads();
    }

    /** Uses {@code threads} render threads from now on (a new pool if the count changed). */
    public void configure(int threads, int newDivider) {
        if (threads != tracer.threads()) {
            tracer.close();
            tracer = new Tracer(threads);
            ranges.close();
            ranges = new PixelRanges(threads);
        }
        divider = newDivider;
    }

    /** The view transform frames are encoded through from now on. */
    public void viewTransform(ViewTransform transform) {
        view = transform;
    }

    /**
     * The last frame again, encoded through the view transform now (the exposure or the tone changed): nothing
     * is traced. Null before the first frame.
     */
    public BufferedImage again() {
        if (!anyFrame) {
            return null;
        }
        ViewTransform v = view;
        if (lastMoving) {
            FrameBuffer frame = buffer;
            BufferedImage image = SrgbEncoder.newImage(frame.width(), frame.height());
            int[] pixels = SrgbEncoder.pixels(image);
            ranges.run(frame.width() * frame.height(), (from, to) -> SrgbEncoder.encode(frame, pixels, from, to, v));
            return image;
        }
        BufferedImage image = SrgbEncoder.newImage(accumulator.width(), accumulator.height());
        int[] pixels = SrgbEncoder.pixels(image);
        ranges.run(accumulator.width() * accumulator.height(), (from, to) -> accumulator.encode(pixels, from, to, v));
        return image;
    }

    /** A frame with one sample per pixel, through the pixel centres. */
    public BufferedImage renderMoving(RenderScene scene, int width, int height) {
        FrameBuffer frame = buffer(width, height);
        anyFrame = false;
        tracer.traceOnly(null);
        call.trace(tracer, scene, frame, 1, TraceCall.WHOLE_FRAME, 1, divider);
        BufferedImage image = SrgbEncoder.newImage(width, height);
        int[] pixels = SrgbEncoder.pixels(image);
        ViewTransform v = view;
        ranges.run(width * height, (from, to) -> SrgbEncoder.encode(frame, pixels, from, to, v));
        lastMoving = true;
        anyFrame = true;
        return image;
    }

    /**
     * Pass {@code pass} of the still image of {@code samples} samples per pixel, averaged with the
     * passes before it (pass 0 starts over; after a failed pass the engine starts over).
     */
    BufferedImage renderPass(RenderScene scene, int width, int height, int samples, int pass) {
        return renderPasses(scene, width, height, samples, pass, 1);
    }

    /** Passes {@code pass} .. {@code pass + count - 1} traced in one go, averaged with those before them. */
    public BufferedImage renderPasses(RenderScene scene, int width, int height, int samples, int pass, int count) {
        return renderPasses(scene, width, height, samples, pass, count, 0, Integer.MAX_VALUE);
    }

    /**
     * {@link #renderPasses(RenderScene, int, int, int, int, int)} with adaptive sampling: a pixel whose noise is
     * below {@code threshold} (0: none) stops receiving passes ({@link glint.render.Convergence}); every pixel
     * stops at {@code cap} passes. The threshold and cap are taken at pass 0.
     */
    public BufferedImage renderPasses(RenderScene scene, int width, int height, int samples, int pass, int count,
                                      double threshold, int cap) {
        anyFrame = false; // before the reset: memory running out there leaves no refinement to read
        if (pass == 0) {
            accumulator.reset(width, height, threshold, cap);
        }
        FrameBuffer frame = buffer(width, height);
        tracer.traceOnly(accumulator.convergence().active());
        try {
            call.trace(tracer, scene, frame, samples, pass, count, divider);
        } finally {
            tracer.traceOnly(null);
        }
        BufferedImage image = SrgbEncoder.newImage(width, height);
        int[] pixels = SrgbEncoder.pixels(image);
        accumulator.beginPasses(count);
        ViewTransform v = view;
        ranges.run(width * height, (from, to) -> accumulator.addAndEncode(frame, pixels, from, to, v));
        accumulator.passesAdded();
        lastMoving = false;
        anyFrame = true;
        return image;
    }

    /**
     * How many of {@code wanted} passes the next call of the refinement may trace: never past its cap, nor past
     * the end of a round where pixels may converge (all of them before the first pass).
     */
    public int inOneCall(int wanted, int done) {
        return done == 0 ? wanted : accumulator.convergence().inOneCall(wanted);
    }

    /**
     * Whether the refinement on screen has nothing left to trace: every pixel converged, or the cap reached.
     * False before a still pass.
     */
    public boolean refinementDone() {
        return !lastMoving && anyFrame && accumulator.convergence().done();
    }

    /** Whether the refinement on screen stopped because every pixel converged, before the cap. */
    public boolean converged() {
        return refinementDone() && accumulator.convergence().activePixels() == 0
                && accumulator.passes() < accumulator.convergence().cap();
    }

    /** The noise left in the still passes on screen, relative to their brightness ({@link Accumulator#relativeNoise}). */
    public double relativeNoise() {
        return accumulator.relativeNoise();
    }

    private FrameBuffer buffer(int width, int height) {
        if (buffer == null || buffer.width() != width || buffer.height() != height) {
            buffer = null; // the old one can go before the new one is taken
            buffer = new FrameBuffer(width, height);
        }
        return buffer;
    }

    @Override
    public void close() {
        tracer.close();
        ranges.close();
    }
}
