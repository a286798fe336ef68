/**
 * What the engine hands the display, without one: a complete frame with the overlay's figures
 * ({@link glint.ui.screen.ShownFrame}, {@link glint.ui.screen.FrameStats}) to a
 * {@link glint.ui.screen.Presenter}, the overlay's lines ({@link glint.ui.screen.OverlayText}) and a frame
 * scaled to the window ({@link glint.ui.screen.WindowImages}). The display draws them
 * ({@link glint.ui.swing.Display}).
 */
package glint.ui.screen;
