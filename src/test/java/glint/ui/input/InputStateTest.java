package glint.ui.input;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.ui.FakeClock;
import glint.ui.Poll;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** Held keys are integrated over time between engine updates; commands and pointer input queue up. */
class InputStateTest {

    private final FakeClock clock = new FakeClock();
    private final InputState input = new InputState(clock, 800, 600);

    @Test
    void heldTimeIsSplitBetweenUpdates() {
        input.press(Action.FORWARD);
        clock.advance(0.3);
        InputFrame first = input.drain();
        assertEquals(0.3, first.seconds(Action.FORWARD), 1e-9);
        assertTrue(first.motionHeld());
        clock.advance(0.2);
        assertEquals(0.2, input.drain().seconds(Action.FORWARD), 1e-9);
        clock.advance(0.1);
        input.release(Action.FORWARD);
        clock.advance(0.4);
        InputFrame last = input.drain();
        assertEquals(0.1, last.seconds(Action.FORWARD), 1e-9);
        assertFalse(last.motionHeld());
        clock.advance(1);
        assertEquals(0, input.drain().seconds(Action.FORWARD));
    }

    @Test
    void aTapBetweenTwoUpdatesStillCounts() {
        clock.advance(5); // idle for a while: the wait before the press must not count
        input.press(Action.YAW_LEFT);
        clock.advance(0.05);
        input.release(Action.YAW_LEFT);
        clock.advance(0.5);
        assertEquals(0.05, input.drain().seconds(Action.YAW_LEFT), 1e-9);
    }

    @Test
    void autoRepeatDoesNotRestartTheKey() {
        input.press(Action.RIGHT);
        clock.advance(0.2);
        input.press(Action.RIGHT);
        clock.advance(0.2);
        assertEquals(0.4, input.drain().seconds(Action.RIGHT), 1e-9);
    }

    @Test
    void releaseAllEndsEveryHeldKey() {
        input.press(Action.FORWARD);
        input.press(Action.FAST);
        clock.advance(0.25);
        input.releaseAll();
        assertFalse(input.isDown(Action.FORWARD));
        clock.advance(1);
        InputFrame in = input.drain();
        assertEquals(0.25, in.seconds(Action.FORWARD), 1e-9);
        assertFalse(in.fast());
        assertFalse(in.motionHeld());
    }

    @Test
    void fastIsTheModifierNow() {
        input.press(Action.FAST);
        InputFrame in = input.drain();
        assertTrue(in.fast());
        assertFalse(in.motionHeld(), "Shift alone does not move");
    }

    @Test
    void commandsDragAndWheelAreTakenOnce() {
        input.command(Action.SCREENSHOT);
        input.command(Action.DEPTH_UP);
        input.drag(3, -4);
        input.drag(1, 1);
        input.wheel(-1);
        input.wheel(-2);
        InputFrame in = input.drain();
        assertEquals(List.of(Action.SCREENSHOT, Action.DEPTH_UP), in.commands());
        assertEquals(4, in.dragX());
        assertEquals(-3, in.dragY());
        assertEquals(-3, in.wheelNotches());
        InputFrame next = input.drain();
        assertEquals(List.of(), next.commands());
        assertEquals(0, next.dragX());
        assertEquals(0, next.wheelNotches());
    }

    @Test
    void resizeKeepsAtLeastOnePixel() {
        input.resize(1024, 0);
        assertEquals(1024, input.viewWidth());
        assertEquals(1, input.viewHeight());
    }

    @Test
    void activityBeforeTheWaitIsNotLost() throws Exception {
        input.command(Action.RELOAD);
        Waiting wait = waitFor(TimeUnit.SECONDS.toNanos(30));
        assertTrue(wait.result(), "the command came first: the wait ends without the clock moving");
        assertEquals(List.of(), clock.waitsLeft());
        assertFalse(input.awaitActivity(0), "the command ended one wait, not two");
    }

    @Test
    void anotherThreadWakesTheWait() throws Exception {
        input.awaitActivity(0); // clear
        Waiting wait = waitFor(TimeUnit.SECONDS.toNanos(30));
        Poll.until(() -> clock.waitsLeft().equals(List.of(TimeUnit.SECONDS.toNanos(30))), 10_000, "the wait began");
        Thread waker = new Thread(() -> input.press(Action.FORWARD));
        waker.start();
        assertTrue(wait.result(), "ended by the key, the clock still where it was");
        waker.join();
        assertEquals(List.of(), clock.waitsLeft());
    }

    @Test
    void withoutActivityTheWaitEndsWhenTheClockHasMovedByTheTimeout() throws Exception {
        assertFalse(input.awaitActivity(0), "nothing happened: a wait of no time ends at once");
        long timeout = TimeUnit.MILLISECONDS.toNanos(20);
        Waiting wait = waitFor(timeout);
        Poll.until(() -> clock.waitsLeft().equals(List.of(timeout)), 10_000, "the wait began");
        clock.advanceNanos(timeout - 1);
        assertEquals(List.of(1L), clock.waitsLeft(), "one nanosecond short of the timeout, it goes on");
        assertTrue(wait.thread.isAlive());
        clock.advanceNanos(1);
        assertFalse(wait.result(), "it timed out: no input came");
        assertEquals(List.of(), clock.waitsLeft());
    }

    @Test
    void onTheSystemClockTheWaitEndsOnActivityOrTimesOut() throws InterruptedException {
        InputState real = new InputState(Clock.SYSTEM, 800, 600);
        assertFalse(real.awaitActivity(TimeUnit.MILLISECONDS.toNanos(1)), "nothing happened");
        real.wheel(1);
        assertTrue(real.awaitActivity(Long.MAX_VALUE), "the wheel came first");
    }

    /** {@link InputState#awaitActivity} on a thread of its own; {@link #result} joins it. */
    private final class Waiting {
        final Thread thread;
        volatile Boolean woken;

        Waiting(long timeoutNanos) {
            thread = new Thread(() -> {
                try {
                    woken = input.awaitActivity(timeoutNanos);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, "test-wait");
            thread.start();
        }

        /** Whether input ended the wait; fails if the wait has not ended within a generous safety net. */
        boolean result() throws InterruptedException {
            thread.join(20_000);
            assertFalse(thread.isAlive(), "the wait did not end");
            return woken;
        }
    }

    private Waiting waitFor(long timeoutNanos) {
        return new Waiting(timeoutNanos);
    }
}
