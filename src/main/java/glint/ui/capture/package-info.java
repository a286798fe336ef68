/**
 * The view kept: screenshots (F12, {@link glint.ui.capture.Screenshots}), stills rendered in the background
 * (Enter, {@link glint.ui.capture.StillRender}), both started by {@link glint.ui.capture.Captures}; the camera
 * as a scene's block (C, {@link glint.ui.capture.CameraBlock}); standard output checked line by line
 * ({@link glint.ui.capture.Printing}). No display needed.
 */
package glint.ui.capture;
