package glint.ui.capture;

import glint.image.ViewTransform;
import glint.input.InputException;
import glint.math.Vector3d;
import glint.scene.Camera;
import glint.scenefile.SceneLoader;
import java.math.BigDecimal;
import java.math.RoundingMode;

/**
 * A camera written as the {@code camera:} block of a scene file (key C): position, a look_at one unit
 * ahead, the camera's up and its field of view, and, for a lens (an aperture above 0), its aperture and
 * focus (a pinhole's block has neither: its picture does not depend on the focus, and a pinhole's scene
 * stays as it was written). Pasted into a scene, or under {@code views:}, it gives the
 * same picture: the numbers keep six decimals, a hundred-thousandth of a degree of the view. A scene far
 * smaller or larger than a unit (a position of 5e-20, or 1e20) keeps its numbers whole instead, and a
 * camera far from the origin looks at a point as much farther ahead as six decimals need.
 */
public final class CameraBlock {

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
    public static String print(Camera camera, java.io.PrintWriter out, java.io.PrintWriter err) {
        return print(camera, null, out, err);
    }

    /**
     * {@link #print(Camera, java.io.PrintWriter, java.io.PrintWriter)} with, last, a comment saying the view
     * transform the picture is seen with, as the keys of a scene's {@code render:} block:
     * {@code # seen with render: {exposure: 1.5, tone: neutral}}.
     */
    public static String print(Camera camera, ViewTransform view, java.io.PrintWriter out, java.io.PrintWriter err) {
        String text = blocks(camera) + (view == null ? "" : seenWith(view) + "\n");
        String failed = Printing.print(out, text);
        if (failed == null) {
            return text.strip();
        }
        err.println("glint: camera not printed: " + failed);
        return "camera not printed: " + failed;
    }

    /** The view transform as a comment of {@code render:} keys. */
    static String seenWith(ViewTransform view) {
        return "# seen with render: {exposure: " + number(view.exposure()) + ", tone: " + view.tone().key() + "}";
    }

    /** The camera as an item of a scene's {@code views:} list, indented as under the key: {@code - {...}}. */
    static String viewItem(Camera camera) {
        Vector3d p = camera.position();
        String lens = camera.aperture() > 0
                ? ", aperture: " + length(camera.aperture()) + ", focus: " + length(camera.focus()) : "";
        return "  - {position: " + vector(p) + ", look_at: " + vector(lookAt(camera))
                + ", up: " + vector(camera.orientation().up()) + ", fov: " + fov(camera.fovDegrees()) + lens + "}";
    }

    /** The camera a scene holding the printed block has: the block read back as the scene loader reads it. */
    static Camera asPrinted(Camera camera) {
        try {
            return SceneLoader.parse("camera", yaml(camera)).camera();
        } catch (InputException e) { // a camera no block can hold (turned, 1e300 out): the still is of it as it is
            return camera;
        }
    }

    /** The block, four lines under {@code camera:} (six with a lens), each ending in a newline. */
    static String yaml(Camera camera) {
        Vector3d p = camera.position();
        String lens = camera.aperture() > 0
                ? "  aperture: " + length(camera.aperture()) + "\n" + "  focus: " + length(camera.focus()) + "\n" : "";
        return "camera:\n"
                + "  position: " + vector(p) + "\n"
                + "  look_at: " + vector(lookAt(camera)) + "\n"
                + "  up: " + vector(camera.orientation().up()) + "\n"
                + "  fov: " + fov(camera.fovDegrees()) + "\n"
                + lens;
    }

    /**
     * A field of view (strictly between 0 and 180 degrees): six decimals where they keep it within a
     * millionth of itself and strictly inside that range, else the shortest decimal that reads back as
     * it is, so 179.9999999 is not printed as 180 nor 1e-7 as 0, which no scene takes.
     */
    static String fov(double degrees) {
        String six = number(degrees);
        double read = Double.parseDouble(six);
        return read > 0 && read < 180 && Math.abs(read - degrees) <= 1e-6 * degrees ? six : whole(degrees);
    }

    /** A length (above 0): six decimals when they keep it (1e-3 to 1e15), else whole, as {@link #vector}. */
    private static String length(double x) {
        return x >= 1e-3 && x < 1e15 ? number(x) : whole(x);
    }

    /**
     * A point ahead of the camera: one unit, or a millionth of the position's distance from the origin
     * when that is more (at 1e20, one unit ahead would round to the position itself), at most 1e150,
     * the farthest a scene's look_at may be.
     */
    private static Vector3d lookAt(Camera camera) {
        Vector3d p = camera.position();
        return p.add(camera.orientation().forward().scale(Math.min(1e150, Math.max(1, largest(p) * 1e-6))));
    }

    private static double largest(Vector3d v) {
        return Math.max(Math.abs(v.x()), Math.max(Math.abs(v.y()), Math.abs(v.z())));
    }

    /**
     * Six decimals when the vector's largest number is of a size six decimals keep (1e-3 to 1e15);
     * otherwise every number whole, as the shortest decimal that reads back as it is.
     */
    private static String vector(Vector3d v) {
        double largest = largest(v);
        if (largest == 0 || largest >= 1e-3 && largest < 1e15) {
            return "[" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + "]";
        }
        return "[" + whole(v.x()) + ", " + whole(v.y()) + ", " + whole(v.z()) + "]";
    }

    /** The shortest decimal that reads back as x: {@code 5.0E-20}; 0 as {@code 0}. */
    static String whole(double x) {
        return x == 0 ? "0" : Double.toString(x);
    }

    /** Six decimals at most, no trailing zeros, no minus zero. */
    static String number(double x) {
        String s = BigDecimal.valueOf(x).setScale(6, RoundingMode.HALF_EVEN).stripTrailingZeros().toPlainString();
        return s.equals("-0") ? "0" : s;
    }
}
