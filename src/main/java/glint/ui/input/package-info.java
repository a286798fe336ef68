/**
 * What the user does and the camera it flies: the one table of keys ({@link glint.ui.input.KeyBindings},
 * {@link glint.ui.input.Action}), the input gathered between two turns of the engine
 * ({@link glint.ui.input.InputState}, {@link glint.ui.input.InputFrame}) on the {@link glint.ui.input.Clock},
 * and the camera it moves ({@link glint.ui.input.CameraController}, {@link glint.ui.input.OrbitPivot}). A new
 * key is a row of the table and an action here; what a command key does is the engine's
 * {@link glint.ui.engine.Commands}. No display needed.
 */
package glint.ui.input;
