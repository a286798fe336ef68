package glint.scenefile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.input.InputException;
import glint.registry.MaterialType;
import glint.registry.Registry;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * Every material type against every key some type reads, and every typo of one letter of those keys:
 * a key is read by its type or refused with the fix, and a hint never names a key the type refuses,
 * so following the message loads.
 */
class MaterialKeysTest {

    private static final Pattern HINT = Pattern.compile("\\(did you mean '([^']+)'\\?\\)$");
    private static final Pattern FIX = Pattern.compile("; write type: (\\w+)(?: or type: \\w+)*, or remove (\\w+)\\)$");

    private static String scene(String type, String key) {
        String value = key.equals("color") ? "[0.5, 0.5, 0.5]" : "0.5"; // in the range of every key
        return "materials:\n  m: {type: " + type + ", " + key + ": " + value + "}\n";
    }

    private static Set<String> everyTypesKeys() {
        Set<String> keys = new LinkedHashSet<>();
        Registry.STANDARD.materials().forEach(type -> keys.addAll(type.keys()));
        return keys;
    }

    /** The words one deletion, one doubled letter or one swap of neighbours away from {@code key}. */
    private static List<String> typos(String key) {
        List<String> typos = new ArrayList<>();
        for (int i = 0; i < key.length(); i++) {
            typos.add(key.substring(0, i) + key.substring(i + 1));
            typos.add(key.substring(0, i + 1) + key.charAt(i) + key.substring(i + 1));
            if (i + 1 < key.length()) {
                typos.add(key.substring(0, i) + key.charAt(i + 1) + key.charAt(i) + key.substring(i + 2));
            }
        }
        typos.removeIf(typo -> typo.isEmpty() || typo.equals(key));
        return typos;
    }

    private static String error(String text) {
        return assertThrows(InputException.class, () -> SceneLoader.parse("m.yaml", text)).getMessage();
    }

    @Test
    void aKeyIsReadByItsTypeOrRefusedWithAFixThatLoads() throws InputException {
        for (MaterialType type : Registry.STANDARD.materials()) {
            for (String key : everyTypesKeys()) {
                if (type.keys().contains(key)) {
                    SceneLoader.parse("m.yaml", scene(type.name(), key));
                    continue;
                }
                String message = error(scene(type.name(), key));
                Matcher fix = FIX.matcher(message);
                assertTrue(fix.find(), message);
                assertEquals(key, fix.group(2), message);
                assertTrue(Registry.STANDARD.material(fix.group(1)).keys().contains(key), message);
                SceneLoader.parse("m.yaml", scene(fix.group(1), key));
            }
        }
    }

    @Test
    void aTyposHintIsAKeyOfTheMaterialsOwnTypeAndLoads() throws InputException {
        int hints = 0;
        for (MaterialType type : Registry.STANDARD.materials()) {
            for (String key : everyTypesKeys()) {
                for (String typo : typos(key)) {
                    if (everyTypesKeys().contains(typo)) {
                        continue; // a key itself ("ks" from "kd"?): not a typo
                    }
                    String message = error(scene(type.name(), typo));
                    int column = "  m: {type: ".length() + type.name().length() + ", ".length() + 1;
                    String unknown = "m.yaml:2:" + column + ": unknown key '" + typo + "' in material 'm' (";
                    assertTrue(message.startsWith(unknown), message);
                    Matcher hint = HINT.matcher(message);
                    if (hint.find()) {
                        hints++;
                        assertTrue(type.keys().contains(hint.group(1)), message);
                        SceneLoader.parse("m.yaml", scene(type.name(), hint.group(1)));
                    } else {
                        assertTrue(message.endsWith("(expected one of: type, " + String.join(", ", type.keys()) + ")"),
                                message);
                    }
                }
            }
        }
        assertTrue(hints > 0, "some typo is close enough to a key for a hint");
    }
}
