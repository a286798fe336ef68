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
    void twoSizesThatWouldReadTheSameAreGivenInBytes() {
        // a PFM of 4,097 bytes under a limit of 4,096: "4.0 KB, more than 4.0 KB" would say nothing
        assertEquals(java.util.List.of("4,097 bytes", "4,096 bytes"), java.util.List.of(TextFiles.sizes(4097, 4096)));
        assertEquals(java.util.List.of("234.4 KB", "4.0 KB"), java.util.List.of(TextFiles.sizes(240_012, 4096)));
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
    void cutTextCountsCharactersNotUtf16Units() {
        // 60 emoji are 120 UTF-16 units and 60 characters: shown whole; 61 are cut after the 60th
        assertEquals("'" + "😀".repeat(60) + "'", InputException.quote("😀".repeat(60)));
        assertEquals("'" + "😀".repeat(60) + "...'", InputException.quote("😀".repeat(61)));
        String path = "/" + "😀".repeat(200) + ".png";
        assertEquals("/" + "😀".repeat(59) + "..." + "😀".repeat(56) + ".png", InputException.cutPath(path));
    }

    @Test
    void aNumberBeyondALimitShowsAsManyDigitsAsTellThemApart() {
        assertEquals("2.00e+30", InputException.beyond(2e30, 1e30, 3));
        assertEquals("1.0000001e+30", InputException.beyond(1.0000001e30, 1e30, 3));
        assertEquals("3.0e+160", InputException.beyond(3e160, 1e150, 2));
        assertEquals("1.0000000000000002e+30", InputException.beyond(Math.nextUp(1e30), 1e30, 3));
    }

    @Test
    void aUtf32FileIsNamedUtf32NotUtf16() {
        for (String charset : java.util.List.of("UTF-32", "UTF-32BE", "UTF-32LE")) {
            InputException e = assertThrows(InputException.class, () -> TextFiles.utf8("f",
                    "objects: []\n".getBytes(java.nio.charset.Charset.forName(charset))));
            assertEquals("f:1:1: not UTF-8 text: the file looks like UTF-32 (save it as UTF-8)", e.getMessage(), charset);
        }
        for (String charset : java.util.List.of("UTF-16", "UTF-16BE", "UTF-16LE")) {
            InputException e = assertThrows(InputException.class, () -> TextFiles.utf8("f",
                    "objects: []\n".getBytes(java.nio.charset.Charset.forName(charset))));
            assertEquals("f:1:1: not UTF-8 text: the file looks like UTF-16 (save it as UTF-8)", e.getMessage(), charset);
        }
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
