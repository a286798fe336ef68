package glint.ui.swing;

import glint.ui.frames.FrameRenderer;
import glint.ui.screen.Presenter;
import java.util.function.UnaryOperator;

/**
 * The two places where tests reach into a real window: how frames are traced (a fault injected into a
 * tile, a stamp on each frame) and what the engine presents to (a checker in front of the display). The
 * program itself uses {@link #NONE}.
 *
 * @param trace     how the engine traces a frame
 * @param presenter wraps the window's display, the engine's presenter
 */
record WindowHooks(FrameRenderer.TraceCall trace, UnaryOperator<Presenter> presenter) {

    static final WindowHooks NONE = new WindowHooks(FrameRenderer.TraceCall.TRACER, p -> p);
}
