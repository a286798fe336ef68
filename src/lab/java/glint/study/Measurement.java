package glint.study;

/**
 * One scene under one configuration: its median frame time and its error against a reference.
 *
 * @param scene     scene name
 * @param config    the configuration
 * @param millis    median wall time of a frame, ms
 * @param cpuMillis median CPU time of a frame, ms (all render threads together)
 * @param errors    its errors against the reference
 */
public record Measurement(String scene, StudyConfig config, double millis, double cpuMillis, ImageErrors errors) {

    public double relMse() {
        return errors.relMse();
    }

    public double ssim() {
        return errors.ssim();
    }

    public double flip() {
        return errors.flip();
    }
}
