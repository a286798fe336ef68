package glint.ui.screen;

/** Where the engine hands its complete frames: the window's display, or a test. */
public interface Presenter {

    /** Shows a complete frame; must not block on painting. Called from the engine thread. */
    void present(ShownFrame frame);

    /** The window title changed (config {@code name} after a reload). */
    default void title(String title) {
    }
}
