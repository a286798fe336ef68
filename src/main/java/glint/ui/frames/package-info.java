/**
 * The window's frame images: a one-sample frame while the camera moves, at the scale the
 * {@link glint.ui.frames.ResolutionGovernor} allows, and the refinement at rest: how many passes and in
 * which pattern ({@link glint.ui.frames.Refinement}), how many in one call
 * ({@link glint.ui.frames.RefinePacing}), their average ({@link glint.ui.frames.Accumulator}), encoded to
 * 8-bit sRGB ({@link glint.ui.frames.SrgbEncoder}) on several threads ({@link glint.ui.frames.PixelRanges}),
 * all through {@link glint.ui.frames.FrameRenderer}. How far the refinement of the view has come is the
 * view's ({@link glint.ui.view.SceneView}). No display needed.
 */
package glint.ui.frames;
