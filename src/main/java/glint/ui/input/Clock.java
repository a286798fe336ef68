package glint.ui.input;

/** A source of monotonic time, injected so that tests can drive the engine deterministically. */
@FunctionalInterface
public interface Clock {

    Clock SYSTEM = System::nanoTime;

    /** Monotonic nanoseconds, as {@link System#nanoTime()}. */
    long nanoTime();
}
