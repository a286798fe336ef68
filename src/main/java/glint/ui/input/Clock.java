package glint.ui.input;

import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.Lock;
import java.util.function.BooleanSupplier;

/**
 * A source of monotonic time, injected so that tests can drive the engine deterministically: it times held
 * keys, and the waits of the engine's loop end when it says so.
 */
@FunctionalInterface
public interface Clock {

    Clock SYSTEM = System::nanoTime;

    /** Monotonic nanoseconds, as {@link System#nanoTime()}. */
    long nanoTime();

    /**
     * Waits on {@code condition} until {@code woken} holds or {@code nanos} of this clock have passed, and
     * returns whether {@code woken} holds. The calling thread holds {@code lock}, the condition's lock;
     * {@code woken} is read under it, at the start and each time the condition is signalled.
     *
     * <p>This waits out real time, which is right for the system's clock and any clock that flows with it; a
     * clock that moves otherwise (a test's, moved by hand) overrides it, to end the wait when it has moved
     * far enough.
     */
    default boolean await(Lock lock, Condition condition, long nanos, BooleanSupplier woken)
            throws InterruptedException {
        long left = nanos;
        while (!woken.getAsBoolean() && left > 0) {
            left = condition.awaitNanos(left);
        }
        return woken.getAsBoolean();
    }
}
