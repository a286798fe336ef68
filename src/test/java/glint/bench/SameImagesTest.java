package glint.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;

import glint.image.FrameBuffer;
import glint.image.ImageWriter;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Two images compared as the reference images' README measures them. */
class SameImagesTest {

    @Test
    void theSameBytesHaveNoErrorAndAChangedValueItsShare(@TempDir Path folder) throws Exception {
        FrameBuffer a = new FrameBuffer(2, 1), b = new FrameBuffer(2, 1);
        a.set(0, 0, 1, 0.5, 0.25);
        b.set(0, 0, 1, 0.5, 0.25);
        b.set(1, 0, 0.1, 0, 0); // a's is black: (0.1 - 0)^2 / (0 + 0.01) = 1, over 6 values
        Path pathA = folder.resolve("a.pfm"), pathB = folder.resolve("b.pfm"), same = folder.resolve("same.pfm");
        ImageWriter.write(a, pathA);
        ImageWriter.write(b, pathB);
        ImageWriter.write(a, same);
        assertEquals(0, SameImages.relativeMse(pathA, same));
        assertEquals(1.0 / 6, SameImages.relativeMse(pathA, pathB), 1e-6);
    }
}
