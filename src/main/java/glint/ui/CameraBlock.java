package glint.ui;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.scene.Camera;
import glint.scene.SceneLoader;
import java.math.BigDecimal;
import java.math.RoundingMode;

/**
 * A camera written as the {@code camera:} block of a scene file (key C): position, a look_at one unit
 * ahead, the camera's up and its field of view. Pasted into a scene, or under {@code views:}, it gives the
 * same picture: the numbers keep six decimals, a hundred-thousandth of a degree of the view.
 */
final class CameraBlock {

    private CameraBlock() {
    }

    /**
     * What key C prints: the {@code camera:} block and the same camera as a one-line item of {@code views:},
     * ready to paste under a scene's {@code views:}; the whole is a scene of its own, too.
     */
    static String blocks(Camera camera) {
        return yaml(camera) + "views:\n" + viewItem(camera) + "\n";
    }

    /**
     * Prints {@link #blocks} (key C) and returns it for the overlay; if standard output does not take it,
     * returns why, and says so on {@code err}.
     */
    static String print(Camera camera, java.io.PrintWriter out, java.io.PrintWriter err) {
        String text = blocks(camera);
        String failed = Printing.print(out, text);
        if (failed == null) {
            return text.strip();
        }
        err.println("glint: camera not printed: " + failed);
        return "camera not printed: " + failed;
    }

    /** The camera as an item of a scene's {@code views:} list, indented as under the key: {@code - {...}}. */
    static String viewItem(Camera camera) {
        Vector3d p = camera.position();
        return "  - {position: " + vector(p) + ", look_at: " + vector(p.add(camera.orientation().forward()))
                + ", up: " + vector(camera.orientation().up()) + ", fov: " + number(camera.fovDegrees()) + "}";
    }

    /** The camera a scene holding the printed block has: the block read back as the scene loader reads it. */
    static Camera asPrinted(Camera camera) {
        try {
            return SceneLoader.parse("camera", yaml(camera)).camera();
        } catch (InputException e) { // cannot happen: the block of a camera is a valid scene
            throw new IllegalStateException(e.getMessage(), e);
        }
    }

    /** The block, four lines under {@code camera:}, each ending in a newline. */
    static String yaml(Camera camera) {
        Vector3d p = camera.position();
        Vector3d forward = camera.orientation().forward();
        return "camera:\n"
                + "  position: " + vector(p) + "\n"
                + "  look_at: " + vector(p.add(forward)) + "\n"
                + "  up: " + vector(camera.orientation().up()) + "\n"
                + "  fov: " + number(camera.fovDegrees()) + "\n";
    }

    private static String vector(Vector3d v) {
        return "[" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + "]";
    }

    /** Six decimals at most, no trailing zeros, no minus zero. */
    static String number(double x) {
        String s = BigDecimal.valueOf(x).setScale(6, RoundingMode.HALF_EVEN).stripTrailingZeros().toPlainString();
        return s.equals("-0") ? "0" : s;
    }
}
