package glint.ui.input;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.ui.FakeClock;
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
    void activityBeforeTheWaitIsNotLost() throws InterruptedException {
        input.command(Action.RELOAD);
        long start = System.nanoTime();
        input.awaitActivity(TimeUnit.SECONDS.toNanos(30)); // returns at once: the command came first
        assertTrue(System.nanoTime() - start < TimeUnit.SECONDS.toNanos(5));
    }

    @Test
    void anotherThreadWakesTheWait() throws InterruptedException {
        input.awaitActivity(0); // clear
        Thread waker = new Thread(() -> input.press(Action.FORWARD));
        long start = System.nanoTime();
        waker.start();
        input.awaitActivity(TimeUnit.SECONDS.toNanos(30));
        assertTrue(System.nanoTime() - start < TimeUnit.SECONDS.toNanos(5));
        waker.join();
    }

    @Test
    void withoutActivityTheWaitTimesOut() throws InterruptedException {
        input.awaitActivity(0); // clear
        long start = System.nanoTime();
        input.awaitActivity(TimeUnit.MILLISECONDS.toNanos(20));
        assertTrue(System.nanoTime() - start >= TimeUnit.MILLISECONDS.toNanos(20));
    }
}
