package glint.ui;

import glint.ui.input.Clock;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.Lock;
import java.util.function.BooleanSupplier;

/**
 * A clock that moves only when told to. A wait timed by it ({@link #await}) ends when it is woken or when the
 * clock has been moved past its end, never because real time passed; {@link #waitsLeft} tells a test who
 * waits on it and for how much longer, and {@link #advance} returns once every wait it woke has seen the new
 * time (the wait is over, or it goes on for what is left).
 */
public final class FakeClock implements Clock {

    /** A wait in progress: whose condition to signal, when it ends, the time it last saw. */
    private static final class Wait {
        final Lock lock;
        final Condition condition;
        final long end;
        long seen;

        Wait(Lock lock, Condition condition, long end, long seen) {
            this.lock = lock;
            this.condition = condition;
            this.end = end;
            this.seen = seen;
        }
    }

    private volatile long now = 1_000_000_000L;
    private final List<Wait> waits = new ArrayList<>(); // guarded by this

    @Override
    public long nanoTime() {
        return now;
    }

    public void advance(double seconds) {
        advanceNanos(Math.round(seconds * 1e9));
    }

    /**
     * Moves the clock on by {@code nanos}, wakes every wait on it, and returns once each has seen the new time.
     */
    public void advanceNanos(long nanos) {
        List<Wait> woken;
        long to;
        synchronized (this) {
            now += nanos;
            to = now;
            woken = List.copyOf(waits);
        }
        for (Wait w : woken) {
            w.lock.lock();
            try {
                w.condition.signalAll();
            } finally {
                w.lock.unlock();
            }
        }
        long giveUp = System.nanoTime() + TimeUnit.SECONDS.toNanos(20); // a safety net, not a measure
        synchronized (this) {
            while (woken.stream().anyMatch(w -> waits.contains(w) && w.seen < to)) {
                long left = giveUp - System.nanoTime();
                if (left <= 0) {
                    throw new AssertionError("a wait on the clock did not see it move within 20 s");
                }
                try {
                    TimeUnit.NANOSECONDS.timedWait(this, left);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new AssertionError("interrupted while the waits saw the clock move", e);
                }
            }
        }
    }

    /** For each wait on this clock in progress, the nanoseconds of the clock until it ends, in the order they began. */
    public synchronized List<Long> waitsLeft() {
        return waits.stream().map(w -> w.end - now).toList();
    }

    @Override
    public boolean await(Lock lock, Condition condition, long nanos, BooleanSupplier woken)
            throws InterruptedException {
        Wait wait;
        synchronized (this) {
            wait = new Wait(lock, condition, nanos > Long.MAX_VALUE - now ? Long.MAX_VALUE : now + nanos, now);
            waits.add(wait);
        }
        try {
            while (!woken.getAsBoolean() && wait.seen < wait.end) {
                condition.await();
                synchronized (this) {
                    wait.seen = now;
                    notifyAll();
                }
            }
            return woken.getAsBoolean();
        } finally {
            synchronized (this) {
                waits.remove(wait);
                notifyAll();
            }
        }
    }
}
