package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The generated part of a doc is replaced, the hand-written rest kept. */
class GeneratedSectionTest {

    @Test
    void replacesOnlyBetweenItsMarkers(@TempDir Path dir) throws Exception {
        Path doc = dir.resolve("doc.md");
        Files.writeString(doc, "# Title\nprose\n<!-- generated:t -->\nold\n<!-- /generated:t -->\nmore prose\n");
        GeneratedSection.write(doc, "t", "new table\n");
        assertEquals("# Title\nprose\n<!-- generated:t -->\nnew table\n<!-- /generated:t -->\nmore prose\n",
                Files.readString(doc));
    }

    @Test
    void appendsTheSectionWhenTheMarkersAreMissing(@TempDir Path dir) throws Exception {
        Path doc = dir.resolve("doc.md");
        Files.writeString(doc, "# Title");
        GeneratedSection.write(doc, "t", "body");
        assertEquals("# Title\n\n<!-- generated:t -->\nbody\n<!-- /generated:t -->\n", Files.readString(doc));
    }
}
