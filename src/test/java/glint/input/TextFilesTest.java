package glint.input;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Reading the files a user names: the reason a read fails, sizes in messages, what reaches the terminal. */
class TextFilesTest {

    @Test
    void theReasonAFileCannotBeReadIsKept() {
        assertEquals("scene.yaml: cannot read: permission denied",
                TextFiles.unreadable("scene.yaml", new AccessDeniedException("scene.yaml")).getMessage());
        assertEquals("scene.yaml: cannot read: Input/output error", TextFiles.unreadable("scene.yaml",
                new FileSystemException("scene.yaml", null, "Input/output error")).getMessage());
    }

    @Test
    void anUnreadableFileSaysPermissionDenied(@TempDir Path dir) throws IOException {
        Path file = Files.writeString(dir.resolve("s.yaml"), "camera: {}\n");
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("---------"));
        assumeFalse(Files.isReadable(file), "running as root: every file is readable");
        InputException e = assertThrows(InputException.class, () -> TextFiles.readBounded(file, 100, n -> "big"));
        assertEquals(file + ": cannot read: permission denied", e.getMessage());
    }

    @Test
    void sizesAreGivenInTheUnitThatReads() {
        assertEquals("1 byte", TextFiles.size(1));
        assertEquals("1023 bytes", TextFiles.size(1023));
        assertEquals("1.5 KB", TextFiles.size(1536));
        assertEquals("8.0 MB", TextFiles.size(8L << 20));
        assertEquals("the file is 700 bytes; the limit is 1 byte", TextFiles.fileIsLargerThan(700, 1, "the limit"));
    }

    @Test
    void messagesNeverHoldLineBreaksOrTerminalEscapes() {
        // ESC [2J clears the screen; U+202E turns the text after it around
        assertEquals("f:1:2: unknown 'a\\nb\\r\\t\\u001b[2J\\u202e'",
                new InputException("f", 1, 2, "unknown 'a\nb\r\t\u001b[2J\u202e'").getMessage());
        assertEquals("plain text stays the same: é, ü, 名", InputException.printable("plain text stays the same: é, ü, 名"));
    }

    @Test
    void quotedUserTextIsCutToSixtyCharacters() {
        assertEquals("'" + "k".repeat(60) + "...'", InputException.quote("k".repeat(8 << 20)));
        assertEquals("'short'", InputException.quote("short"));
    }

    @Test
    void controlCharactersOfBothRangesAreRefusedWhereTheyStand() {
        // U+009B is a one-character terminal escape (CSI); U+0085 (next line) is allowed by YAML
        InputException e = assertThrows(InputException.class, () -> TextFiles.utf8("f", "a: 1\n# \u0085 \u009b\n"
                .getBytes(java.nio.charset.StandardCharsets.UTF_8)));
        assertEquals("f:2:5: not a text file: control character U+009B (only tab and line breaks are allowed)",
                e.getMessage());
    }
}
