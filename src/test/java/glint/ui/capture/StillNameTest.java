package glint.ui.capture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** A still's name begins with its scene's: whole when short, else shortened, in bytes, with a code of the whole. */
class StillNameTest {

    @Test
    void aShortSceneNameIsKeptWhole() {
        assertEquals("phong-classic", StillRender.stem(Path.of("scenes/phong-classic.yaml")));
        assertEquals("a".repeat(100), StillRender.stem(Path.of("a".repeat(100) + ".yaml")));
    }

    @Test
    void aLongNameIsCutToAHundredBytesOfWholeCharactersAndACodeOfTheWhole() {
        String name = "\u00e9".repeat(30) + "\uD83D\uDE00".repeat(10) + "a".repeat(205); // 245 characters, 305 bytes
        String stem = StillRender.stem(Path.of(name + ".yaml"));
        assertTrue(stem.matches("\u00e9{30}(\uD83D\uDE00){7}-[0-9a-f]{8}"), stem); // 60 + 28 + 9 bytes: no half emoji
        assertTrue(stem.getBytes(StandardCharsets.UTF_8).length <= StillRender.STEM_BYTES, stem);
        assertNotEquals(stem, StillRender.stem(Path.of(name + "b.yaml")), "names that differ at the end");
        assertEquals(stem, StillRender.stem(Path.of("elsewhere", name + ".yml")), "the same name, the same stem");
    }
}
