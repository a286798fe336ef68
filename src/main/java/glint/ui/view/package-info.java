/**
 * What is on screen: the scene, the camera flying through it and the settings it is seen with, the scene
 * compiled for them, and how far the refinement has come ({@link glint.ui.view.SceneView}, which alone
 * changes the camera, the {@link glint.ui.view.ViewSettings} and the window's size and frame budget
 * ({@link glint.ui.view.FrameSize}), and starts the frame over when it does); the overlay's message
 * ({@link glint.ui.view.StatusLine}). Engine thread. No display needed.
 */
package glint.ui.view;
