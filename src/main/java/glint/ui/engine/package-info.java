/**
 * The window's loop ({@link glint.ui.engine.Engine}): one turn is input, camera, render, present, on a
 * thread of its own. Its parts: the command keys ({@link glint.ui.engine.Commands}), frames made and tried
 * again when they fail ({@link glint.ui.engine.FrameMaker}, {@link glint.ui.engine.RenderFaults}), and handed
 * to the display with the overlay's figures ({@link glint.ui.engine.FrameOutput}). The engine puts the other
 * packages' parts together; nothing here needs a display.
 */
package glint.ui.engine;
