package glint.ui;

import glint.ui.swing.GlintWindow;
import java.awt.Point;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;
import javax.swing.SwingUtilities;

/** Waiting in tests for what another thread (the engine, the watcher, Swing) does, without fixed sleeps. */
public final class Poll {

    private Poll() {
    }

    /**
     * Checks {@code condition} every few milliseconds until it holds; fails with {@code what} and the
     * deadline if it does not within {@code deadlineMillis}. Returns the milliseconds it took.
     */
    public static long until(BooleanSupplier condition, long deadlineMillis, Supplier<String> what)
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
    public static long until(BooleanSupplier condition, long deadlineMillis, String what) throws InterruptedException {
        return until(condition, deadlineMillis, () -> what);
    }

    /** The value of {@code task} computed on the Swing event thread. */
    public static <T> T onEventThread(Supplier<T> task) throws Exception {
        Object[] result = new Object[1];
        SwingUtilities.invokeAndWait(() -> result[0] = task.get());
        @SuppressWarnings("unchecked")
        T t = (T) result[0];
        return t;
    }

    /** Clicks the middle of the window's display and waits until it holds the keyboard focus. */
    public static void clickToFocus(GlintWindow window, Robot robot, Supplier<String> what) throws Exception {
        Point centre = onEventThread(() -> {
            Point p = window.display().getLocationOnScreen();
            return new Point(p.x + window.display().getWidth() / 2, p.y + window.display().getHeight() / 2);
        });
        robot.mouseMove(centre.x, centre.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        until(() -> window.display().isFocusOwner(), 10_000, what);
    }
}
