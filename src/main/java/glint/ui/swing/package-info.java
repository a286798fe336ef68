/**
 * The window on a display, and the only Swing: {@link glint.ui.swing.GlintWindow} puts the frame, the
 * engine's thread and the scene watcher together; {@link glint.ui.swing.Display} paints the newest frame
 * and the overlay; {@link glint.ui.swing.InputListener} turns AWT events into the engine's input.
 */
package glint.ui.swing;
