package glint.study;

/**
 * One scene under one configuration: its median frame time and its error against the reference.
 *
 * @param scene  scene name
 * @param config the configuration
 * @param millis median wall time of a frame, ms
 * @param cpuMillis median CPU time of a frame, ms (all render threads together)
 * @param relMse relative MSE against the reference (linear values)
 * @param ssim   SSIM against the reference (sRGB luma)
 */
public record Measurement(String scene, StudyConfig config, double millis, double cpuMillis, double relMse,
                          double ssim) {
}
