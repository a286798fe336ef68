package glint.input;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A missing file's message names a file of the folder it is a typo of, and no other. */
class SimilarFileTest {

    private static final List<String> SCENES = List.of("default.yaml", "glass.yaml", "field.yaml", "metals.yaml");

    @Test
    void anotherCaseOrALetterOffIsTheFileMeant() {
        assertEquals("default.yaml", TextFiles.closestFileName("Default.yaml", SCENES));
        assertEquals("glass.yaml", TextFiles.closestFileName("glas.yaml", SCENES));
        assertEquals("default.yaml", TextFiles.closestFileName("defualt.yaml", SCENES));
    }

    /** .yml is the other common ending of YAML: the scene of the same name, or a letter off, is meant. */
    @Test
    void theYmlEndingMeansTheYamlFile() {
        assertEquals("glass.yaml", TextFiles.closestFileName("glass.yml", SCENES));
        assertEquals("glass.yaml", TextFiles.closestFileName("glas.yml", SCENES));
        assertEquals("metals.yml", TextFiles.closestFileName("metals.yaml", List.of("metals.yml")));
        assertEquals("default.yaml", TextFiles.closestFileName("DEFAULT.YML", SCENES));
    }

    @Test
    void aNameUnlikeAnyOrOfAnotherKindHasNoSuggestion() {
        assertNull(TextFiles.closestFileName("nope.properties", List.of("empty.properties")));
        assertNull(TextFiles.closestFileName("x.yaml", List.of("a.yaml")));
        assertNull(TextFiles.closestFileName("default.png", SCENES));
        assertNull(TextFiles.closestFileName("telephoto.yaml", SCENES));
    }

    @Test
    void theMessageOfAMissingFileNamesTheOneMeantInItsFolder(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("default.yaml"), "");
        Path missing = dir.resolve("Default.yaml");
        InputException e = TextFiles.unreadable(missing.toString(), new java.nio.file.NoSuchFileException(missing.toString()));
        assertEquals(missing + ": no such file (did you mean '" + dir.resolve("default.yaml") + "'?)", e.getMessage());
        Path other = dir.resolve("other.yaml");
        Path yml = dir.resolve("default.yml");
        assertEquals(yml + ": no such file (did you mean '" + dir.resolve("default.yaml") + "'?)",
                TextFiles.unreadable(yml.toString(), new java.nio.file.NoSuchFileException(yml.toString())).getMessage());
        assertEquals(other + ": no such file",
                TextFiles.unreadable(other.toString(), new java.nio.file.NoSuchFileException(other.toString())).getMessage());
    }
}
