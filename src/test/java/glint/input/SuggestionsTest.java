package glint.input;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

class SuggestionsTest {

    private static final List<String> SPHERE_KEYS = List.of("type", "center", "radius", "material");

    @Test
    void distanceOfKnownPairs() {
        assertEquals(0, Suggestions.distance("radius", "radius"));
        assertEquals(1, Suggestions.distance("radus", "radius"));   // one deletion
        assertEquals(1, Suggestions.distance("radiuss", "radius")); // one insertion
        assertEquals(1, Suggestions.distance("radies", "radius"));  // one substitution
        assertEquals(2, Suggestions.distance("fvo", "fov"));        // a swap is two edits
        assertEquals(3, Suggestions.distance("kitten", "sitting"));
        assertEquals(2, Suggestions.distance("flaw", "lawn"));
        assertEquals(3, Suggestions.distance("", "abc"));
        assertEquals(3, Suggestions.distance("abc", ""));
        assertEquals(0, Suggestions.distance("", ""));
        assertEquals(1, Suggestions.distance("Type", "type"));      // distance itself is case-sensitive
    }

    @Test
    void distanceIsSymmetric() {
        assertEquals(Suggestions.distance("intensty", "intensity"), Suggestions.distance("intensity", "intensty"));
        assertEquals(Suggestions.distance("cook-torrance", "phong"), Suggestions.distance("phong", "cook-torrance"));
    }

    @Test
    void hintForATypo() {
        assertEquals(" (did you mean 'radius'?)", Suggestions.hint("radus", SPHERE_KEYS));
        assertEquals(" (did you mean 'material'?)", Suggestions.hint("materal", SPHERE_KEYS));
    }

    @Test
    void hintIgnoresCase() {
        assertEquals(" (did you mean 'radius'?)", Suggestions.hint("RADIUS", SPHERE_KEYS));
        assertEquals(" (did you mean 'phong'?)", Suggestions.hint("Phong", List.of("cook-torrance", "phong")));
    }

    @Test
    void hintListsTheKnownWordsInTheirOrderWhenNoneIsClose() {
        assertEquals(" (expected one of: type, center, radius, material)", Suggestions.hint("colour", SPHERE_KEYS));
        assertEquals(" (expected one of: cook-torrance, phong)",
                Suggestions.hint("bogus", List.of("cook-torrance", "phong")));
    }

    @Test
    void twoEditsAreAlwaysCloseEnough() {
        assertEquals(" (did you mean 'fov'?)", Suggestions.hint("fvo", List.of("position", "look_at", "up", "fov")));
        assertEquals(" (did you mean 'kd'?)", Suggestions.hint("k", List.of("kd")));
    }

    @Test
    void longWordsAllowAThirdOfTheirLength() {
        List<String> types = List.of("point", "directional");
        // "directional" has 11 letters: up to 3 edits suggest it, 4 do not
        assertEquals(3, Suggestions.distance("dirctonl", "directional"));
        assertEquals(" (did you mean 'directional'?)", Suggestions.hint("dirctonl", types));
        assertEquals(4, Suggestions.distance("drctonl", "directional"));
        assertEquals(" (expected one of: point, directional)", Suggestions.hint("drctonl", types));
        // "point" has 5 letters: the limit is 2
        assertEquals(3, Suggestions.distance("spot", "point"));
        assertEquals(" (expected one of: point, directional)", Suggestions.hint("spot", types));
    }

    @Test
    void theFirstOfEquallyCloseWordsWins() {
        assertEquals(" (did you mean 'ax'?)", Suggestions.hint("ab", List.of("ax", "ay")));
        assertEquals(" (did you mean 'ay'?)", Suggestions.hint("ab", List.of("ay", "ax")));
    }
}
