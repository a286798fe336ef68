package glint.ui.capture;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Screenshots: new names, never a file left half written, the permissions of every other output. */
class ScreenshotsTest {

    @TempDir
    Path dir;

    @Test
    void aScreenshotHasTheFolderUsualPermissionsNotATemporaryFilesPrivateOnes() throws Exception {
        Path shot = new Screenshots(dir).save(new BufferedImage(4, 3, BufferedImage.TYPE_INT_RGB));
        Path plain = Files.createFile(dir.resolve("plain.txt")); // made with the process's umask, 0644 as a rule
        assertEquals(Files.getPosixFilePermissions(plain), Files.getPosixFilePermissions(shot));
    }

    @Test
    void twoInOneMillisecondGetTwoNamesAndNoTemporaryFileStays() throws Exception {
        LocalDateTime at = LocalDateTime.of(2026, 12, 2, 15, 30, 0, 123_000_000);
        Screenshots shots = new Screenshots(dir, () -> at);
        BufferedImage image = new BufferedImage(4, 3, BufferedImage.TYPE_INT_RGB);
        Path a = shots.save(image);
        Path b = shots.save(image);
        assertEquals("glint-20261202-153000-123.png", a.getFileName().toString());
        assertEquals("glint-20261202-153000-123-1.png", b.getFileName().toString());
        try (var files = Files.list(dir)) {
            assertEquals(List.of(b, a), files.sorted().toList());
        }
    }

    /**
     * F12 on a full disk (its stream on /dev/full, where every write fails as on a full disk): the overlay and
     * standard error name the screenshot and the system's reason, not the encoder's "I/O error writing PNG
     * file!", and nothing is left in the folder.
     */
    @Test
    void aScreenshotOnAFullDiskNamesItsFileAndWhyAndLeavesNothing() throws Exception {
        java.io.File full = new java.io.File("/dev/full");
        org.junit.jupiter.api.Assumptions.assumeTrue(full.canWrite(), "/dev/full is here");
        LocalDateTime at = LocalDateTime.of(2026, 12, 2, 15, 30, 0, 123_000_000);
        Screenshots shots = new Screenshots(dir, () -> at, part -> new java.io.FileOutputStream(full));
        java.io.StringWriter err = new java.io.StringWriter();
        String said = shots.saveView(new BufferedImage(64, 48, BufferedImage.TYPE_INT_RGB),
                new glint.ui.frames.ResolutionGovernor.Size(64, 48), "", new java.io.PrintWriter(err, true));
        String expected = "screenshot not saved: cannot write '" + dir.resolve("glint-20261202-153000-123.png")
                + "': No space left on device";
        assertEquals(expected, said);
        assertEquals("glint: " + expected + System.lineSeparator(), err.toString());
        try (var files = Files.list(dir)) {
            assertEquals(List.of(), files.toList(), "no screenshot, no hidden file");
        }
    }
}
