package glint.ui.input;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/**
 * The user's input, written by the Swing event thread and read by the engine thread. For every
 * held action it integrates how long it was held between two engine updates, so that motion
 * depends on elapsed time only, never on the frame rate. Every change also wakes the engine.
 */
public final class InputState {

    private static final int ACTIONS = Action.values().length;

    private final Clock clock;
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition activity = lock.newCondition();
    private final long[] pressedAt = new long[ACTIONS]; // nanoTime of the press; only where down[]
    private final boolean[] down = new boolean[ACTIONS];
    private final double[] heldSeconds = new double[ACTIONS];
    private final List<Action> commands = new ArrayList<>();
    private long lastDrain;
    private double dragX;
    private double dragY;
    private int wheel;
    private int view = -1;
    private double orbitFromX = Double.NaN;
    private double orbitFromY = Double.NaN;
    private double orbitX;
    private double orbitY;
    private double focusX = Double.NaN;
    private double focusY = Double.NaN;
    private int viewWidth;
    private int viewHeight;
    private boolean signalled;

    public InputState(Clock clock, int viewWidth, int viewHeight) {
        this.clock = clock;
        this.lastDrain = clock.nanoTime();
        this.viewWidth = viewWidth;
        this.viewHeight = viewHeight;
    }

    /** A held action's key went down (repeats while it is down are ignored). */
    public void press(Action action) {
        lock.lock();
        try {
            int i = action.ordinal();
            if (!down[i]) {
                down[i] = true;
                pressedAt[i] = clock.nanoTime();
            }
            signalLocked();
        } finally {
            lock.unlock();
        }
    }

    /** A held action's key went up. */
    public void release(Action action) {
        lock.lock();
        try {
            releaseLocked(action.ordinal(), clock.nanoTime());
            signalLocked();
        } finally {
            lock.unlock();
        }
    }

    /** Releases every held key (the window lost the keyboard focus). */
    public void releaseAll() {
        lock.lock();
        try {
            long now = clock.nanoTime();
            for (int i = 0; i < ACTIONS; i++) {
                releaseLocked(i, now);
            }
            signalLocked();
        } finally {
            lock.unlock();
        }
    }

    /** A one-shot command (screenshot, reload, quit, ...). */
    public void command(Action action) {
        lock.lock();
        try {
            commands.add(action);
            signalLocked();
        } finally {
            lock.unlock();
        }
    }

    /** Key {@code index + 1}: go to the scene's view {@code index} (0 to 8). */
    public void view(int index) {
        lock.lock();
        try {
            commands.add(Action.VIEW);
            view = index;
            signalLocked();
        } finally {
            lock.unlock();
        }
    }

    /** The mouse was dragged by (dx, dy) pixels, y downwards. */
    public void drag(double dx, double dy) {
        lock.lock();
        try {
            dragX += dx;
            dragY += dy;
            signalLocked();
        } finally {
            lock.unlock();
        }
    }

    /** An orbit drag starts at pixel (x, y) of the view: the engine picks the point there. */
    public void orbitFrom(double x, double y) {
        lock.lock();
        try {
            orbitFromX = x;
            orbitFromY = y;
            orbitX = 0; // a drag before the press belongs to the old pivot, which is gone
            orbitY = 0;
            signalLocked();
        } finally {
            lock.unlock();
        }
    }

    /** A click (no drag) at pixel (x, y) of the view: the engine focuses the lens on the point there. */
    public void focusAt(double x, double y) {
        lock.lock();
        try {
            focusX = x;
            focusY = y;
            signalLocked();
        } finally {
            lock.unlock();
        }
    }

    /** The mouse was dragged by (dx, dy) pixels while orbiting, y downwards. */
    public void orbit(double dx, double dy) {
        lock.lock();
        try {
            orbitX += dx;
            orbitY += dy;
            signalLocked();
        } finally {
            lock.unlock();
        }
    }

    /** The mouse wheel turned by {@code notches} (negative: away from the user). */
    public void wheel(int notches) {
        lock.lock();
        try {
            wheel += notches;
            signalLocked();
        } finally {
            lock.unlock();
        }
    }

    /** The drawing area now has this size in pixels. */
    public void resize(int width, int height) {
        lock.lock();
        try {
            viewWidth = Math.max(1, width);
            viewHeight = Math.max(1, height);
            signalLocked();
        } finally {
            lock.unlock();
        }
    }

    public int viewWidth() {
        lock.lock();
        try {
            return viewWidth;
        } finally {
            lock.unlock();
        }
    }

    public int viewHeight() {
        lock.lock();
        try {
            return viewHeight;
        } finally {
            lock.unlock();
        }
    }

    /** Whether a held action is down now. */
    public boolean isDown(Action action) {
        lock.lock();
        try {
            return down[action.ordinal()];
        } finally {
            lock.unlock();
        }
    }

    /** Takes everything since the previous drain. */
    public InputFrame drain() {
        lock.lock();
        try {
            long now = clock.nanoTime();
            boolean motionHeld = false;
            for (int i = 0; i < ACTIONS; i++) {
                if (down[i]) {
                    heldSeconds[i] += seconds(now - Math.max(pressedAt[i], lastDrain));
                    motionHeld |= Action.values()[i].kind() == Action.Kind.MOTION;
                }
            }
            lastDrain = now;
            InputFrame frame = new InputFrame(heldSeconds, down[Action.FAST.ordinal()], motionHeld,
                    dragX, dragY, wheel, commands, view, orbitFromX, orbitFromY, orbitX, orbitY, focusX, focusY);
            Arrays.fill(heldSeconds, 0);
            commands.clear();
            dragX = 0;
            dragY = 0;
            wheel = 0;
            view = -1;
            orbitFromX = Double.NaN;
            orbitFromY = Double.NaN;
            orbitX = 0;
            orbitY = 0;
            focusX = Double.NaN;
            focusY = Double.NaN;
            return frame;
        } finally {
            lock.unlock();
        }
    }

    /** Wakes a thread waiting in {@link #awaitActivity} (for example: the scene file changed). */
    public void signal() {
        lock.lock();
        try {
            signalLocked();
        } finally {
            lock.unlock();
        }
    }

    /**
     * Waits until there is input or a signal, or {@code timeoutNanos} of the clock passed; returns at once
     * if something happened since the last wait. Returns whether input or a signal ended it.
     */
    public boolean awaitActivity(long timeoutNanos) throws InterruptedException {
        lock.lock();
        try {
            boolean woken = clock.await(lock, activity, timeoutNanos, () -> signalled);
            signalled = false;
            return woken;
        } finally {
            lock.unlock();
        }
    }

    private void releaseLocked(int i, long now) {
        if (down[i]) {
            heldSeconds[i] += seconds(now - Math.max(pressedAt[i], lastDrain));
            down[i] = false;
        }
    }

    private void signalLocked() {
        signalled = true;
        activity.signalAll();
    }

    private static double seconds(long nanos) {
        return Math.max(0, nanos) / 1e9;
    }
}
