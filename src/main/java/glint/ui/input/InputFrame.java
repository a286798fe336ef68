package glint.ui.input;

import java.util.ArrayList;
import java.util.List;

/**
 * What the user did since the previous engine update, as taken from {@link InputState#drain}.
 *
 * @param heldSeconds   by {@link Action#ordinal()}: how long each held action was held in the interval
 * @param fast          whether the fast modifier is held now
 * @param motionHeld    whether any motion key is held now
 * @param dragX         mouse drag to the right since the last update, in pixels
 * @param dragY         mouse drag downwards since the last update, in pixels
 * @param wheelNotches  wheel rotation since the last update (negative: away from the user)
 * @param commands      commands in the order they were given
 * @param view          the view (0 to 8) the last {@link Action#VIEW} command asked for, or -1
 * @param orbitFromX    where an orbit drag started in the interval (pixels from the left), or NaN
 * @param orbitFromY    where it started (pixels from the top), or NaN
 * @param orbitX        orbit drag to the right since the last update, in pixels
 * @param orbitY        orbit drag downwards since the last update, in pixels
 * @param focusX        where the last click of the interval was (pixels from the left), or NaN for none
 * @param focusY        where it was (pixels from the top), or NaN
 */
public record InputFrame(double[] heldSeconds, boolean fast, boolean motionHeld, double dragX, double dragY,
                         int wheelNotches, List<Action> commands, int view, double orbitFromX, double orbitFromY,
                         double orbitX, double orbitY, double focusX, double focusY) {

    public InputFrame {
        heldSeconds = heldSeconds.clone();
        commands = List.copyOf(commands);
    }

    /** Nothing happened. */
    public static InputFrame none() {
        return new InputFrame(new double[Action.values().length], false, false, 0, 0, 0, List.of(), -1,
                Double.NaN, Double.NaN, 0, 0, Double.NaN, Double.NaN);
    }

    /** Whether the user clicked in the interval (the lens is then focused on the point there). */
    public boolean focusClicked() {
        return !Double.isNaN(focusX);
    }

    /** Whether an orbit drag started in the interval (its point is then picked). */
    public boolean orbitStarted() {
        return !Double.isNaN(orbitFromX);
    }

    /** Seconds {@code action} was held in the interval. */
    public double seconds(Action action) {
        return heldSeconds[action.ordinal()];
    }

    /** Builds frames for tests and for {@link InputState}. */
    public static final class Builder {
        private final double[] held = new double[Action.values().length];
        private boolean fast;
        private boolean motionHeld;
        private double dragX;
        private double dragY;
        private int wheel;
        private final List<Action> commands = new ArrayList<>();
        private int view = -1;
        private double orbitFromX = Double.NaN;
        private double orbitFromY = Double.NaN;
        private double orbitX;
        private double orbitY;
        private double focusX = Double.NaN;
        private double focusY = Double.NaN;

        public Builder hold(Action action, double seconds) {
            held[action.ordinal()] += seconds;
            if (action.kind() == Action.Kind.MOTION && seconds > 0) {
                motionHeld = true;
            }
            return this;
        }

        public Builder fast(boolean isFast) {
            this.fast = isFast;
            return this;
        }

        public Builder motionHeld(boolean held) {
            this.motionHeld = held;
            return this;
        }

        public Builder drag(double dx, double dy) {
            dragX += dx;
            dragY += dy;
            return this;
        }

        /** An orbit drag that started at pixel (x, y). */
        public Builder orbitFrom(double x, double y) {
            orbitFromX = x;
            orbitFromY = y;
            return this;
        }

        public Builder orbit(double dx, double dy) {
            orbitX += dx;
            orbitY += dy;
            return this;
        }

        /** A click at pixel (x, y). */
        public Builder click(double x, double y) {
            focusX = x;
            focusY = y;
            return this;
        }

        public Builder wheel(int notches) {
            wheel += notches;
            return this;
        }

        public Builder command(Action action) {
            commands.add(action);
            return this;
        }

        /** Key {@code index + 1}: go to view {@code index}. */
        public Builder view(int index) {
            commands.add(Action.VIEW);
            view = index;
            return this;
        }

        public InputFrame build() {
            return new InputFrame(held, fast, motionHeld, dragX, dragY, wheel, commands, view, orbitFromX, orbitFromY,
                    orbitX, orbitY, focusX, focusY);
        }
    }
}
