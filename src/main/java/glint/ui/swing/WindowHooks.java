package glint.ui.swing;

import glint.ui.frames.FrameRenderer;
import glint.ui.input.Clock;
import glint.ui.screen.Presenter;
import java.util.function.UnaryOperator;

/**
 * The places where tests reach into a real window: how frames are traced (a fault injected into a tile, a
 * stamp on each frame), what the engine presents to (a checker in front of the display), and the clock that
 * times held keys and the engine's pauses (a test's, which moves only when told). The program itself uses
 * {@link #NONE}.
 *
 * @param trace     how the engine traces a frame
 * @param presenter wraps the window's display, the engine's presenter
 * @param clock     the input's and the engine's time
 */
record WindowHooks(FrameRenderer.TraceCall trace, UnaryOperator<Presenter> presenter, Clock clock) {

    static final WindowHooks NONE = new WindowHooks(FrameRenderer.TraceCall.TRACER, p -> p, Clock.SYSTEM);

    /** These hooks on the system's clock. */
    WindowHooks(FrameRenderer.TraceCall trace, UnaryOperator<Presenter> presenter) {
        this(trace, presenter, Clock.SYSTEM);
    }
}
