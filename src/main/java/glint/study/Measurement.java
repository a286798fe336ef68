package glint.study;

/**
 * One scene under one configuration: its median frame time and its error against the reference.
 *
 * @param scene  scene name
 * @param config the configuration
 * @param millis median frame time in ms
 * @param relMse relative MSE against the reference (linear values)
 * @param ssim   SSIM against the reference (sRGB luma)
 */
public record Measurement(String scene, StudyConfig config, double millis, double relMse, double ssim) {
}
