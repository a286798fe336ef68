package glint.image;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

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
        // dithered (Dither): 0.5 encodes to 187.516 codes, 188 where the pixel's offset (level + 0.5) / 64 is
        // at least 0.484 (level 31 and up), else 187; 0.18 to 117.646, 118 from level 23; 0 and 1 stay
        int red00 = Dither.channel(Dither.levels(0, 0), 0);
        assertEquals((red00 >= 31 ? 188 : 187) << 16, image.getRGB(0, 0) & 0xFFFFFF);
        int green10 = Dither.channel(Dither.levels(1, 0), 1);
        assertEquals(255 << 16 | (green10 >= 23 ? 118 : 117) << 8 | 255, image.getRGB(1, 0) & 0xFFFFFF);
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

    /** A watcher that stops the write once it has seen the given fraction done, and records what it saw. */
    private static final class Stopping implements ImageWriter.Watcher {
        final double stopAt;
        double seen = -1;

        Stopping(double stopAt) {
            this.stopAt = stopAt;
        }

        @Override
        public void progress(double fraction) {
            seen = Math.max(seen, fraction);
        }

        @Override
        public boolean cancelled() {
            return seen >= stopAt;
        }
    }

    private static FrameBuffer large() {
        FrameBuffer frame = new FrameBuffer(640, 480);
        for (int y = 0; y < 480; y++) {
            for (int x = 0; x < 640; x++) {
                frame.set(x, y, (x * 7 % 255) / 255.0, (y * 13 % 255) / 255.0, ((x ^ y) % 255) / 255.0);
            }
        }
        return frame;
    }

    @Test
    void aCancelledWriteStopsAtItsNextBytesAndLeavesTheImageAsItWas() throws Exception {
        for (String name : java.util.List.of("out.png", "out.pfm")) {
            Path image = dir.resolve(name);
            byte[] old = "the image of the last run".getBytes(StandardCharsets.US_ASCII);
            Files.write(image, old);
            Path temp = ImageWriter.temporaryBeside(image);
            Stopping watcher = new Stopping(0.3);
            org.junit.jupiter.api.Assertions.assertThrows(java.io.InterruptedIOException.class,
                    () -> ImageWriter.writeTemporary(large(), image, temp, watcher));
            org.junit.jupiter.api.Assertions.assertTrue(watcher.seen >= 0.3 && watcher.seen < 1, name + ": " + watcher.seen);
            Path whole = dir.resolve("whole-" + name);
            ImageWriter.write(large(), whole);
            org.junit.jupiter.api.Assertions.assertTrue(Files.size(temp) < Files.size(whole),
                    name + ": stopped before its end");
            Files.delete(whole);
            assertArrayEquals(old, Files.readAllBytes(image), name + ": the old image is untouched");
            Files.delete(temp); // the caller's to delete (a still deletes it as it is cancelled)
            Files.delete(image);
        }
    }

    @Test
    void aTemporaryFilesNameIsShortEvenForALongImageName() throws Exception {
        Path image = dir.resolve("n".repeat(251) + ".png"); // 255 bytes: the longest name a folder takes
        Path temp = ImageWriter.temporaryBeside(image);
        org.junit.jupiter.api.Assertions.assertTrue(temp.getFileName().toString().startsWith("." + "n".repeat(60) + "."),
                temp.getFileName().toString());
        org.junit.jupiter.api.Assertions.assertTrue(temp.getFileName().toString().length() < 100);
        ImageWriter.writeAtomically(image, temp, out -> ImageWriter.writePng(ImageWriter.toImage(sample()), out));
        assertEquals(3, ImageIO.read(image.toFile()).getWidth());
    }
}
