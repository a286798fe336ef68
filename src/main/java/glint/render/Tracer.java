package glint.render;

import glint.image.FrameBuffer;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.concurrent.CancellationException;
import java.util.concurrent.Phaser;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

/**
 * Renders frames with {@link TracerWorker}s on render threads of its own. A frame is split into
 * divider x divider tiles that the workers take in turn, spread over the frame ({@link TileOrder}); every
 * pixel is computed from its own coordinates alone, so the image does not depend on the thread or tile count.
 * <p>
 * Each render thread loops: it waits at its {@link Crew}'s start barrier, does its share of the frame and
 * arrives at the crew's end barrier. A thread that ends for any reason, even an error between frames
 * (memory running out while it waits), terminates both barriers on its way out: the frame under way fails
 * with its error instead of waiting forever for a thread that is gone, and the next frame has a new crew.
 */
public final class Tracer implements AutoCloseable {

    private final int threads;
    private final TracerWorker[] workers;
    private final AtomicInteger nextTile = new AtomicInteger();
    private final AtomicReference<Throwable> failure = new AtomicReference<>();
    /** The render threads and the barriers a frame starts and ends at: a frame allocates nothing of its own. */
    private volatile Crew crew;
    /** Why a render thread of the crew ended, once one has on an error. */
    private final AtomicReference<Throwable> threadEnded = new AtomicReference<>();
    /** For tests: the error a render thread meets between frames, as memory running out in its wait would. */
    private final AtomicReference<Error> betweenFrames = new AtomicReference<>();
    private volatile boolean closed;
    /** Light the bidirectional integrator's paths bring to other pixels than their own, per frame. */
    private final Splats splats = new Splats();
    /** The light subpaths of a bidirectional pass that camera paths merge with. */
    private final LightVertices lightVertices = new LightVertices();
    /**
     * Heap bytes a pixel of a bidirectional frame takes besides the frame itself: a pass's own image (3
     * floats), the sum of the passes (3 doubles) and the splats (3 longs). The light subpaths' vertices come
     * on top, at most {@link BdptIntegrator#MOST_LIGHT_PATHS} subpaths of them, as many as the scene makes.
     */
    public static final long BIDIRECTIONAL_BYTES_PER_PIXEL = 3 * 4 + 3 * 8 + 3 * 8;
    /** A bidirectional pass's own image and the sum of a frame's passes, per pixel and channel. */
    private FrameBuffer passFrame;
    private double[] passSum = new double[0];
    /** What the workers do when started: the tiles of the frame, or a pass's light subpaths to merge with. */
    private volatile boolean tracingLightPaths;
    private final AtomicInteger nextChunk = new AtomicInteger();
    private volatile int chunks;
    /** The CPU time the thread that renders spent on the workers' behalf (the merge grid), in ns. */
    private long ownCpuNanos;
    /** Per worker: the CPU time its thread spent rendering frames, in ns; written by it, read after a frame. */
    private final long[] workerCpuNanos;
    /** Reads the render threads' CPU clocks; null where the JVM cannot. */
    private final ThreadMXBean cpuClock;

    // progress and cancelling: counted per tile, never per pixel
    /** Tiles finished in the frame being rendered (or the last one). */
    private final AtomicInteger tilesDone = new AtomicInteger();
    private volatile int frameTiles = 1;
    private volatile boolean cancelled;

    // the frame being rendered; written before the workers start, read by them
    private volatile RenderScene scene;
    private volatile FrameBuffer frame;
    private volatile int samples;
    private volatile int firstSample;
    private volatile int sampleCount;
    private volatile int frameIndex;
    private volatile int divider;
    private volatile int tileStride;
    /** The pixels traced (row by row), or null for all; set between frames ({@link #traceOnly}). */
    private volatile boolean[] only;

    public Tracer(int threads) {
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be >= 1, got " + threads);
        }
        this.threads = threads;
        this.workers = new TracerWorker[threads];
        for (int i = 0; i < threads; i++) {
            workers[i] = new TracerWorker();
        }
        this.workerCpuNanos = new long[threads];
        ThreadMXBean bean = ManagementFactory.getThreadMXBean();
        this.cpuClock = bean.isCurrentThreadCpuTimeSupported() && bean.isThreadCpuTimeEnabled() ? bean : null;
        this.crew = new Crew();
    }

    /** The render threads, one a worker, and the two barriers they meet at each frame; made again whole. */
    private final class Crew {
        final Phaser start = new Phaser(threads + 1), done = new Phaser(threads + 1);
        final Thread[] members = new Thread[threads];

        Crew() {
            for (int i = 0; i < threads; i++) {
                int index = i;
                members[i] = new Thread(() -> serve(index, this), "glint-tracer-" + (i + 1));
                members[i].setDaemon(true);
            }
            try {
                for (Thread member : members) {
                    member.start();
                }
            } catch (Throwable t) { // memory running out: the members started leave, and frames fail on t
                threadEnded.compareAndSet(null, t);
                end();
                throw t;
            }
        }

        /** Ends the crew: its members leave once their share of the frame under way is done. Allocates nothing. */
        void end() {
            start.forceTermination();
            done.forceTermination();
        }

        /** Waits for every member to have left; keeps an interrupt for the caller. */
        void awaitLeft() {
            boolean interrupted = false;
            for (Thread member : members) {
                while (member.isAlive()) {
                    try {
                        member.join();
                    } catch (InterruptedException e) {
                        interrupted = true;
                    }
                }
            }
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** Rays cast by all workers so far (camera, reflected, refracted and shadow rays). */
    public long raysCast() {
        long sum = 0;
        for (TracerWorker worker : workers) {
            sum += worker.raysCast();
        }
        return sum;
    }

    /**
     * CPU time the render threads have spent on frames so far, summed over them, in ns; -1 where the
     * JVM cannot measure a thread's CPU time. Unlike a frame's wall-clock time, it leaves out the
     * time the threads wait for a core, so on a shared machine it shows the renderer's own work.
     */
    public long renderCpuNanos() {
        if (cpuClock == null) {
            return -1;
        }
        long sum = ownCpuNanos;
        for (long nanos : workerCpuNanos) {
            sum += nanos;
        }
        return sum;
    }

    public int threads() {
        return threads;
    }

    /**
     * Renders one frame into {@code target} and returns when every pixel is written.
     *
     * @param samples    samples per pixel, a perfect square
     * @param frameIndex seeds the sample jitter (the same index gives the same image)
     * @param divider    the frame is split into divider x divider tiles
     */
    public void render(RenderScene renderScene, FrameBuffer target, int samples, int frameIndex, int divider) {
        run(renderScene, target, samples, 0, samples, frameIndex, divider);
    }

    /**
     * Renders only pass {@code pass} of a progressive image: sample {@code pass mod samples} of each
     * pixel's stratified pattern of frame index {@code pass / samples}. The average of passes 0 ..
     * samples - 1 equals {@code render(..., samples, 0, ...)}: the window refines progressively towards
     * the still image, and past it (the path integrator) through the patterns of later frames.
     */
    public void renderPass(RenderScene renderScene, FrameBuffer target, int samples, int pass, int divider) {
        renderPasses(renderScene, target, samples, pass, 1, divider);
    }

    /**
     * Passes {@code first} .. {@code first + count - 1} in one go, all of one pattern: their average
     * (the window, when passes are quick).
     */
    public void renderPasses(RenderScene renderScene, FrameBuffer target, int samples, int first, int count, int divider) {
        if (first < 0 || count < 1 || first % samples + count > samples) {
            throw new IllegalArgumentException("passes " + first + " + " + count + " outside one pattern of " + samples);
        }
        run(renderScene, target, samples, first % samples, count, first / samples, divider);
    }

    /**
     * Traces from now on only the pixels whose entry of {@code pixels} (row by row, the frame's size) is true,
     * or every pixel when null: the frame's other pixels are left as they are, and no path starts from them
     * (adaptive sampling, {@link Convergence}). The array is read while a frame renders, so it is changed only
     * between frames. The bidirectional integrator's passes trace all their light subpaths whatever the mask,
     * so each traced pixel's light tracing stays an unbiased estimate.
     */
    public void traceOnly(boolean[] pixels) {
        only = pixels;
    }

    private void run(RenderScene renderScene, FrameBuffer target, int samples, int first, int count,
                     int frameIndex, int divider) {
        this.scene = renderScene;
        this.frame = target;
        this.samples = samples;
        this.firstSample = first;
        this.sampleCount = count;
        this.frameIndex = frameIndex;
        this.divider = Math.max(1, Math.min(divider, Math.min(target.width(), target.height())));
        boolean[] mask = only;
        if (mask != null && mask.length != target.width() * target.height()) {
            throw new IllegalArgumentException("a mask of " + mask.length + " pixels for a frame of "
                    + target.width() + "x" + target.height());
        }
        nextTile.set(0);
        failure.set(null);
        tilesDone.set(0);
        boolean splatting = renderScene != null && renderScene.settings.transport() == LightTransport.BDPT;
        frameTiles = this.divider * this.divider * (splatting ? count : 1);
        tileStride = TileOrder.stride(this.divider * this.divider);
        if (splatting) {
            renderBidirectional(target, first, count, renderScene.settings.merging());
        } else {
            launch();
        }
    }

    /** Runs the workers on the tiles, or on the light subpaths, and waits for them. */
    private void launch() {
        if (cancelled) {
            throw new CancellationException("the render was cancelled");
        }
        if (closed) {
            throw new IllegalStateException("the tracer is closed");
        }
        Crew c = crew;
        boolean done = c.start.arrive() >= 0 && c.done.arriveAndAwaitAdvance() >= 0;
        if (!done) {
            Throwable ended = threadEnded.get();
            if (ended == null) {
                throw new CancellationException("the tracer was closed");
            }
            replaceCrew(c);
            throw new RenderException("a render thread ended: " + ended, ended);
        }
        if (cancelled) {
            throw new CancellationException("the render was cancelled");
        }
        Throwable error = failure.get();
        if (error != null) {
            throw new RenderException("a render worker failed: " + error, error);
        }
    }

    /**
     * After a member of crew {@code c} ended on an error: waits for the others to leave (they finish their
     * share of the frame first, so no two threads ever use one worker), then starts a new crew for the frames
     * to come.
     */
    private void replaceCrew(Crew c) {
        c.awaitLeft();
        threadEnded.set(null);
        crew = new Crew();
        if (closed) { // closed meanwhile, from another thread
            crew.end();
        }
    }

    /** A render thread's life: a share of every frame, until its crew ends or it meets an error. */
    private void serve(int index, Crew c) {
        Throwable end = null;
        try {
            while (c.start.arriveAndAwaitAdvance() >= 0 && !closed) {
                runWorker(index, c.done);
                Error injected = betweenFrames.getAndSet(null);
                if (injected != null) {
                    throw injected;
                }
            }
        } catch (Throwable t) {
            end = t;
        } finally { // allocates nothing: memory may have run out
            if (end != null) {
                threadEnded.compareAndSet(null, end);
            }
            c.end();
        }
    }

    /** For tests: one render thread meets {@code e} after its share of the next frame, outside the frame's work. */
    void failBetweenFrames(Error e) {
        betweenFrames.set(e);
    }

    /**
     * A bidirectional frame, pass by pass: each pass's light subpaths traced, their light tracing splatted,
     * and gridded where the frame merges; then its camera paths, which join them and merge with them, into a
     * pass image; the passes averaged into {@code target}'s traced pixels, and the frame's splats added.
     */
    private void renderBidirectional(FrameBuffer target, int first, int count, boolean merging) {
        if (tracedPixels(target) == 0) {
            return; // no path starts, so no light subpath is wanted either
        }
        int w = target.width(), h = target.height();
        splats.clear(w, h);
        if (passFrame == null || passFrame.width() != w || passFrame.height() != h) {
            passFrame = new FrameBuffer(w, h);
            passSum = new double[3 * w * h];
        }
        Arrays.fill(passSum, 0);
        int paths = BdptIntegrator.lightPaths(w * h);
        double firstRadius = merging ? workers[0].firstMergeRadius(scene, w, h) : 0;
        boolean[] mask = only;
        float[] pass = passFrame.rgb();
        try {
            for (int k = 0; k < count; k++) {
                int sample = first + k;
                double radius = merging ? BdptIntegrator.mergeRadius(firstRadius, (long) frameIndex * samples + sample) : 0;
                chunks = lightVertices.begin(paths, radius);
                for (TracerWorker worker : workers) {
                    worker.pass(lightVertices, splats);
                }
                nextChunk.set(0);
                firstSample = sample;
                sampleCount = 1;
                tracingLightPaths = true;
                launch();
                long start = cpuClock == null ? 0 : cpuClock.getCurrentThreadCpuTime();
                lightVertices.finish();
                if (cpuClock != null) {
                    ownCpuNanos += cpuClock.getCurrentThreadCpuTime() - start;
                }
                tracingLightPaths = false;
                frame = passFrame;
                nextTile.set(0);
                launch();
                for (int i = 0; i < pass.length; i++) {
                    if (mask == null || mask[i / 3]) {
                        passSum[i] += pass[i];
                    }
                }
            }
        } finally {
            tracingLightPaths = false;
            frame = target;
        }
        float[] rgb = target.rgb();
        for (int i = 0; i < rgb.length; i++) {
            if (mask == null || mask[i / 3]) {
                rgb[i] = FrameBuffer.storable(passSum[i] / count);
            }
        }
        splats.addInto(target, 1.0 / count * ((double) (w * h) / paths));
    }

    private int tracedPixels(FrameBuffer target) {
        boolean[] mask = only;
        if (mask == null) {
            return target.width() * target.height();
        }
        int traced = 0;
        for (boolean b : mask) {
            traced += b ? 1 : 0;
        }
        return traced;
    }

    private void runWorker(int index, Phaser frameDone) {
        TracerWorker worker = workers[index];
        long cpuStart = cpuClock == null ? 0 : cpuClock.getCurrentThreadCpuTime();
        try {
            if (tracingLightPaths) {
                for (int c = nextChunk.getAndIncrement(); c < chunks && !cancelled; c = nextChunk.getAndIncrement()) {
                    worker.traceLightPaths(scene, lightVertices, c, frameIndex, firstSample, samples);
                }
                return;
            }
            int tiles = divider * divider;
            for (int tile = nextTile.getAndIncrement(); tile < tiles && !cancelled; tile = nextTile.getAndIncrement()) {
                renderTile(worker, tile);
                tilesDone.incrementAndGet();
            }
        } catch (Throwable t) {
            failure.compareAndSet(null, t);
        } finally {
            if (cpuClock != null) {
                workerCpuNanos[index] += cpuClock.getCurrentThreadCpuTime() - cpuStart;
            }
            frameDone.arrive(); // publishes the CPU time to the thread awaiting the frame
        }
    }

    private void renderTile(TracerWorker worker, int handedOut) {
        FrameBuffer f = frame;
        int d = divider;
        int tile = TileOrder.tile(handedOut, d * d, tileStride); // spread over the frame: progress is a fair sample
        int column = tile % d, row = tile / d;
        int x0 = column * f.width() / d, x1 = (column + 1) * f.width() / d;
        int y0 = row * f.height() / d, y1 = (row + 1) * f.height() / d;
        worker.renderTile(scene, f, splats, samples, firstSample, sampleCount, frameIndex, x0, y0, x1, y1, only);
    }

    // ---------------------------------------------------------------- progress and cancelling

    /** Tiles finished so far in the frame being rendered (all of them once it is done). */
    public int tilesDone() {
        return tilesDone.get();
    }

    /** Tiles of the frame being rendered, or of the last one. */
    public int frameTiles() {
        return frameTiles;
    }

    /**
     * Stops the frame being rendered from any thread: the tiles not yet started are skipped, and
     * {@code render} / {@code renderPass} throw {@link CancellationException} once the tiles under way
     * are done; so does every later call. The frame buffer then holds a partial image.
     */
    public void cancel() {
        cancelled = true;
    }

    /** Ends the render threads once they are idle; a frame after this throws. */
    @Override
    public void close() {
        closed = true;
        crew.end();
    }
}
