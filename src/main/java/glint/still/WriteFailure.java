package glint.still;

import glint.input.InputException;
import java.io.IOException;
import java.nio.file.Path;

/**
 * Why a rendered still could not be written, in one line that names the image, never its hidden file:
 * {@code cannot write out.png: No space left on device}. What no check before the work can foresee: a
 * full disk, a PNG larger than {@code ulimit -f}, the folder removed or renamed during the render.
 */
public final class WriteFailure extends IOException {

    WriteFailure(Path image, IOException cause) {
        this(image, cause, "");
    }

    /** @param after what is said after the reason: {@code  (a.png was written)} */
    WriteFailure(Path image, IOException cause, String after) {
        super("cannot write " + InputException.cutPath(image.toString()) + ": " + OutputFile.reason(cause) + after, cause);
    }
}
