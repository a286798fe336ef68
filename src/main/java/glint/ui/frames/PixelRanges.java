package glint.ui.frames;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicReference;

/**
 * Splits work over a frame's pixels among threads: the caller does one range, helper threads the
 * others, and {@link #run} returns when all are done. The window uses it to add a still pass to the
 * average and encode it while the render threads, which have just finished the pass, are idle.
 */
final class PixelRanges implements AutoCloseable {

    /** Work on pixels {@code from} (inclusive) to {@code to} (exclusive). */
    @FunctionalInterface
    interface Range {
        void run(int from, int to);
    }

    /** Below this many pixels a frame is done by the caller alone: handing over would cost more. */
    static final int MIN_PIXELS_TO_SPLIT = 32_768;

    private final int parts;
    private final ExecutorService helpers;

    /** Work split into {@code parts} ranges (at least 1), {@code parts - 1} of them on helper threads. */
    PixelRanges(int parts) {
        this.parts = Math.max(1, parts);
        this.helpers = this.parts == 1 ? null : Executors.newFixedThreadPool(this.parts - 1, r -> {
            Thread t = new Thread(r, "glint-encode");
            t.setDaemon(true);
            return t;
        });
    }

    int parts() {
        return parts;
    }

    /** Runs {@code range} over pixels 0 to {@code pixels}, split; rethrows the first failure of any part. */
    void run(int pixels, Range range) {
        if (helpers == null || pixels < MIN_PIXELS_TO_SPLIT) {
            range.run(0, pixels);
            return;
        }
        CountDownLatch done = new CountDownLatch(parts - 1);
        AtomicReference<Throwable> failure = new AtomicReference<>();
        for (int k = 1; k < parts; k++) {
            int from = (int) ((long) pixels * k / parts);
            int to = (int) ((long) pixels * (k + 1) / parts);
            helpers.execute(() -> {
                try {
                    range.run(from, to);
                } catch (RuntimeException | Error e) {
                    failure.compareAndSet(null, e);
                } finally {
                    done.countDown();
                }
            });
        }
        try {
            range.run(0, pixels / parts);
        } finally {
            awaitUninterruptibly(done);
        }
        Throwable e = failure.get();
        if (e instanceof RuntimeException r) {
            throw r;
        }
        if (e instanceof Error err) {
            throw err;
        }
    }

    private static void awaitUninterruptibly(CountDownLatch latch) {
        boolean interrupted = false;
        while (true) {
            try {
                latch.await();
                break;
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public void close() {
        if (helpers != null) {
            helpers.shutdownNow();
        }
    }
}
