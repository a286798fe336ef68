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
}
