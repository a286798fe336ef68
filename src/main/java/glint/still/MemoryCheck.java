package glint.still;

import glint.config.Config;
import glint.render.LightTransport;
import glint.render.Tracer;
import java.util.Locale;

/**
 * Refuses, before any memory is taken, a render the Java heap cannot hold: the frame (and the image made
 * from it), the bidirectional integrator's buffers a pixel, and every render thread's row buffers, which
 * grow with the tile width times the samples.
 */
public final class MemoryCheck {

    /**
     * Heap bytes a render thread needs per camera ray of a tile's row (its row buffers: a direction
     * and a radiance, 7 doubles, with room to spare), and per pixel of a still: the float frame (12)
     * and the 8-bit image written from it (4).
     */
    static final long ROW_BYTES_PER_RAY = 64;
    public static final long STILL_BYTES_PER_PIXEL = 16;
    /** Heap bytes a pixel of a frame that is only rendered (timed, never written) needs: the float frame. */
    public static final long FRAME_BYTES_PER_PIXEL = 12;
    /** Heap kept free for everything else: the scene, the JVM's own needs. */
    static final long HEAP_RESERVE = 32L << 20;

    private MemoryCheck() {
    }

    /**
     * The check against the heap free now; where it falls short, once more after a collection (a window
     * that has been flying holds garbage the collector would give back).
     */
    public static void check(Config config, long bytesPerPixel, Runtime runtime) throws StillRefused {
        if (memoryNeeded(config, bytesPerPixel) > freeHeap(runtime) - HEAP_RESERVE) {
            runtime.gc();
        }
        check(config, bytesPerPixel, freeHeap(runtime));
    }

    private static long freeHeap(Runtime runtime) {
        return runtime.maxMemory() - (runtime.totalMemory() - runtime.freeMemory());
    }

    /** The same check against {@code freeHeap} bytes. */
    static void check(Config config, long bytesPerPixel, long freeHeap) throws StillRefused {
        long need = memoryNeeded(config, bytesPerPixel);
        long available = freeHeap - HEAP_RESERVE;
        if (need > available) {
            String needed = megabytes(need), free = megabytes(Math.max(0, available));
            if (needed.equals(free)) { // the difference is less than a megabyte
                needed = String.format(Locale.ROOT, "%,d bytes", need);
                free = String.format(Locale.ROOT, "%,d bytes", Math.max(0, available));
            }
            throw new StillRefused(String.format(Locale.ROOT,
                    "%dx%d at %d %s with %d %s needs about %s of memory; the Java heap has %s free "
                    + "(render fewer pixels, samples or threads, or start Java with a larger -Xmx)",
                    config.displayWidth(), config.displayHeight(), config.samples(),
                    config.samples() == 1 ? "sample" : "samples", config.effectiveThreads(),
                    config.effectiveThreads() == 1 ? "thread" : "threads", needed, free), false);
        }
    }

    /**
     * Heap bytes a render of this config needs, computed in long (no overflow): {@code bytesPerPixel} and
     * what the integrator keeps a pixel of its own (bdpt: {@link Tracer#BIDIRECTIONAL_BYTES_PER_PIXEL}).
     */
    static long memoryNeeded(Config config, long bytesPerPixel) {
        long w = config.displayWidth(), h = config.displayHeight();
        long divider = Math.max(1, Math.min(config.screenDivider(), Math.min(w, h)));
        long tileWidth = (w + divider - 1) / divider;
        long rowRays = tileWidth * config.samples();
        long integrator = config.transport() == LightTransport.BDPT ? Tracer.BIDIRECTIONAL_BYTES_PER_PIXEL : 0;
        return w * h * (bytesPerPixel + integrator) + config.effectiveThreads() * rowRays * ROW_BYTES_PER_RAY;
    }

    private static String megabytes(long bytes) {
        return String.format(Locale.ROOT, "%,d MB", (bytes + (1 << 20) - 1) >> 20);
    }
}
