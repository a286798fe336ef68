package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Path;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The chart commands write under target/ unless told to update docs/ or given a folder. */
class OutputFolderTest {

    @Test
    void stabilityWritesUnderTargetUnlessToldOtherwise() {
        assertEquals(Path.of("target/study"), Stability.output());
        assertEquals(Path.of("docs"), Stability.output("--docs"));
        assertEquals(Path.of("/tmp/x"), Stability.output("--out", "/tmp/x"));
        assertEquals(Path.of("docs"), Stability.output("--docs", "--only", "cone,sized-fireflies"));
    }

    @Test
    void stabilityWritesAllSectionsOrTheOnesNamed() {
        assertEquals(Set.of(), Stability.only("--docs"));
        assertEquals(Set.of("cone", "sized-fireflies"), Stability.only("--out", "x", "--only", "cone,sized-fireflies"));
        assertEquals("no section 'light'; sections: " + String.join(", ", Stability.SECTIONS),
                assertThrows(IllegalArgumentException.class, () -> Stability.only("--only", "light")).getMessage());
    }

    @Test
    void stabilityRefusesTwoChoicesAndUnknownArguments() {
        assertEquals("--docs and --out both choose the output folder; give one",
                assertThrows(IllegalArgumentException.class, () -> Stability.output("--docs", "--out", "x")).getMessage());
        assertEquals("unexpected '--out'; usage: Stability [--docs | --out DIR] [--only SECTION,...]",
                assertThrows(IllegalArgumentException.class, () -> Stability.output("--out")).getMessage());
        assertEquals("unexpected 'docs'; usage: Stability [--docs | --out DIR] [--only SECTION,...]",
                assertThrows(IllegalArgumentException.class, () -> Stability.output("docs")).getMessage());
    }

    @Test
    void speedAccuracyWritesUnderTargetUnlessToldOtherwise() {
        Path root = Path.of("repo");
        assertEquals(Path.of("repo/target/study"), SpeedAccuracy.output(root, false, false, null));
        assertEquals(Path.of("repo/target/study-quick"), SpeedAccuracy.output(root, true, false, null));
        assertEquals(Path.of("repo/docs"), SpeedAccuracy.output(root, false, true, null));
        assertEquals(Path.of("repo/docs"), SpeedAccuracy.output(root, true, true, null));
        assertEquals(Path.of("elsewhere"), SpeedAccuracy.output(root, true, false, Path.of("elsewhere")));
    }
}
