package glint.ui;

import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;
import javax.swing.SwingUtilities;

/** Waiting in tests for what another thread (the engine, the watcher, Swing) does, without fixed sleeps. */
final class Poll {

    private Poll() {
    }

    /**
     * Checks {@code condition} every few milliseconds until it holds; fails with {@code what} and the
     * deadline if it does not within {@code deadlineMillis}. Returns the milliseconds it took.
     */
    static long until(BooleanSupplier condition, long deadlineMillis, Supplier<String> what)
            throws InterruptedException {
        long start = System.nanoTime();
        while (!condition.getAsBoolean()) {
            if (TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start) > deadlineMillis) {
                throw new AssertionError(what.get() + ": not within " + deadlineMillis + " ms");
            }
            Thread.sleep(5);
        }
        return TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
    }

    /** {@link #until} with a fixed description. */
    static long until(BooleanSupplier condition, long deadlineMillis, String what) throws InterruptedException {
        return until(condition, deadlineMillis, () -> what);
    }

    /** The value of {@code task} computed on the Swing event thread. */
    static <T> T onEventThread(Supplier<T> task) throws Exception {
        Object[] result = new Object[1];
        SwingUtilities.invokeAndWait(() -> result[0] = task.get());
        @SuppressWarnings("unchecked")
        T t = (T) result[0];
        return t;
    }
}
