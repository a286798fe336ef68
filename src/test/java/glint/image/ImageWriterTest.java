package glint.image;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import glint.render.FrameBuffer;
import java.awt.image.BufferedImage;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** PFM layout (little-endian, bottom row first) and PNG encoding. */
class ImageWriterTest {

    @TempDir
    Path dir;

    private static FrameBuffer sample() {
        FrameBuffer frame = new FrameBuffer(3, 2);
        frame.set(0, 0, 0.5, 0, 0);       // top-left
        frame.set(2, 1, 0, 0.25, 1e-3);   // bottom-right
        frame.set(1, 0, 2.5, 0.18, 1);    // brighter than 1 survives in PFM
        return frame;
    }

    @Test
    void pfmHasTheSpecHeaderAndBottomRowFirst() throws Exception {
        Path file = dir.resolve("a.pfm");
        ImageWriter.writePfm(sample(), file);
        byte[] bytes = Files.readAllBytes(file);
        byte[] header = "PF\n3 2\n-1.0\n".getBytes(StandardCharsets.US_ASCII);
        assertArrayEquals(header, Arrays.copyOf(bytes, header.length));
        assertEquals(header.length + 3 * 2 * 12, bytes.length);
        ByteBuffer body = ByteBuffer.wrap(bytes, header.length, bytes.length - header.length)
                .order(ByteOrder.LITTLE_ENDIAN);
        // first stored row is the bottom one: pixel (2, 1) is the third of it
        assertEquals(0.25f, body.getFloat(header.length + (2 * 3 + 1) * 4));
        // the top row comes second: pixel (0, 0)
        assertEquals(0.5f, body.getFloat(header.length + (3 * 3) * 4));
    }

    @Test
    void pfmRoundTripsThroughTheReader() throws Exception {
        Path file = dir.resolve("b.pfm");
        FrameBuffer original = sample();
        ImageWriter.writePfm(original, file);
        assertArrayEquals(original.rgb(), PfmReader.read(file).rgb());
    }

    @Test
    void pngHoldsTheSrgbCodes() throws Exception {
        Path file = dir.resolve("c.png");
        ImageWriter.write(sample(), file);
        BufferedImage image = ImageIO.read(file.toFile());
        assertEquals(3, image.getWidth());
        assertEquals(2, image.getHeight());
        assertEquals(188 << 16, image.getRGB(0, 0) & 0xFFFFFF);
        assertEquals(255 << 16 | 118 << 8 | 255, image.getRGB(1, 0) & 0xFFFFFF);
    }

    @Test
    void aWriteThatFailsHalfWayKeepsTheOldImageAndLeavesNoTemporaryFile() throws Exception {
        Path image = dir.resolve("out.png");
        byte[] old = "the image of the last run".getBytes(StandardCharsets.US_ASCII);
        Files.write(image, old);
        java.io.IOException full = new java.io.IOException("No space left on device");
        java.io.IOException thrown = org.junit.jupiter.api.Assertions.assertThrows(java.io.IOException.class,
                () -> ImageWriter.writeAtomically(image, ImageWriter.temporaryBeside(image), out -> {
                    out.write(new byte[100_000]); // part of an image, then the disk is full
                    throw full;
                }));
        assertEquals(full, thrown);
        assertArrayEquals(old, Files.readAllBytes(image), "the old image is untouched");
        try (var files = Files.list(dir)) {
            assertEquals(java.util.List.of(image), files.toList(), "no temporary file left");
        }
    }

    @Test
    void aWrittenImageReplacesTheOldOneWhole() throws Exception {
        Path image = dir.resolve("out.pfm");
        Files.writeString(image, "old");
        ImageWriter.write(sample(), image);
        assertEquals(3, PfmReader.read(image).width());
        try (var files = Files.list(dir)) {
            assertEquals(java.util.List.of(image), files.toList(), "no temporary file left");
        }
    }

    @Test
    void theImageHasTheFolderUsualPermissionsNotATemporaryFilesPrivateOnes() throws Exception {
        Path image = dir.resolve("out.png");
        ImageWriter.write(sample(), image);
        Path plain = Files.createFile(dir.resolve("plain.txt")); // made with the process's umask
        assertEquals(Files.getPosixFilePermissions(plain), Files.getPosixFilePermissions(image));
    }
}
