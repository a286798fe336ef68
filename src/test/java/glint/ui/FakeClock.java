package glint.ui;

import glint.ui.input.Clock;
import java.util.concurrent.atomic.AtomicLong;

/** A clock that moves only when told to. */
public final class FakeClock implements Clock {

    private final AtomicLong now = new AtomicLong(1_000_000_000L);

    @Override
    public long nanoTime() {
        return now.get();
    }

    public void advance(double seconds) {
        now.addAndGet(Math.round(seconds * 1e9));
    }
}
