package glint.ui.input;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.KeyEvent;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * The keys docs/window.md names are the keys the program binds: each key of each row of its controls table,
 * pressed (a key code) or typed (a character), does that row's action, and every key the program binds is
 * named in the row of its action.
 */
class WindowDocKeysTest {

    /** Keys written by name, and their codes (a keypad's arrows and digits are the same key to a reader). */
    private static final Map<String, List<Integer>> NAMED = Map.ofEntries(
            Map.entry("Left arrow", List.of(KeyEvent.VK_LEFT, KeyEvent.VK_KP_LEFT)),
            Map.entry("Right arrow", List.of(KeyEvent.VK_RIGHT, KeyEvent.VK_KP_RIGHT)),
            Map.entry("Up arrow", List.of(KeyEvent.VK_UP, KeyEvent.VK_KP_UP)),
            Map.entry("Down arrow", List.of(KeyEvent.VK_DOWN, KeyEvent.VK_KP_DOWN)),
            Map.entry("Shift", List.of(KeyEvent.VK_SHIFT)),
            Map.entry("Tab", List.of(KeyEvent.VK_TAB)),
            Map.entry("Enter", List.of(KeyEvent.VK_ENTER)),
            Map.entry("Esc", List.of(KeyEvent.VK_ESCAPE)),
            Map.entry("Home", List.of(KeyEvent.VK_HOME)),
            Map.entry("Page Down", List.of(KeyEvent.VK_PAGE_DOWN)),
            Map.entry("Page Up", List.of(KeyEvent.VK_PAGE_UP)),
            Map.entry("F5", List.of(KeyEvent.VK_F5)),
            Map.entry("F12", List.of(KeyEvent.VK_F12)));

    private record Row(String keys, String meaning) {
    }

    private static List<Row> documentedRows() throws IOException {
        List<Row> rows = new ArrayList<>();
        boolean inTable = false;
        for (String line : Files.readAllLines(Path.of("docs/window.md"), StandardCharsets.UTF_8)) {
            if (line.equals("| key | what it does |")) {
                inTable = true;
            } else if (inTable && line.startsWith("| ") && !line.startsWith("|---")) {
                String[] cells = line.substring(2, line.length() - 2).split(" \\| ", 2);
                rows.add(new Row(cells[0].replace("\\|", "|"), cells[1].replace("\\|", "|")));
            } else if (inTable && !line.startsWith("|")) {
                break;
            }
        }
        return rows;
    }

    /** The key codes and typed characters a row's keys column names; pointer rows (the mouse) name none. */
    private static void keysOf(String keys, Set<Integer> codes, Set<Character> chars) {
        if (keys.startsWith("Mouse") || keys.contains("drag") || keys.equals("Click") || keys.contains(" + ")
                && !keys.startsWith("+") || keys.contains(" / ")) {
            return; // the mouse, a combination (Shift + Enter), a key's other meaning (Enter / Esc): the listener's
        }
        if (keys.equals("1 to 9")) {
            for (int d = 1; d <= 9; d++) {
                codes.add(KeyEvent.VK_0 + d);
                codes.add(KeyEvent.VK_NUMPAD0 + d);
            }
            return;
        }
        for (String part : keys.replace("(or ", " or ").replace(")", "").split(" or ")) {
            String key = part.strip();
            if (NAMED.containsKey(key)) {
                codes.addAll(NAMED.get(key));
            } else if (key.length() == 1 && Character.isLetter(key.charAt(0))) {
                codes.add(KeyEvent.getExtendedKeyCodeForChar(key.charAt(0)));
            } else if (key.length() == 1) {
                chars.add(key.charAt(0));
            } else {
                throw new AssertionError("a key the test cannot read: '" + key + "' in '" + keys + "'");
            }
        }
    }

    @Test
    void eachDocumentedKeyDoesItsRowsAction() throws IOException {
        List<Row> rows = documentedRows();
        assertEquals(KeyBindings.ALL.size(), rows.size(), "a row a binding");
        for (int i = 0; i < rows.size(); i++) {
            Row row = rows.get(i);
            KeyBindings.Binding binding = KeyBindings.ALL.get(i);
            assertEquals(binding.meaning(), row.meaning(), "row " + (i + 1));
            Set<Integer> codes = new HashSet<>();
            Set<Character> chars = new HashSet<>();
            keysOf(row.keys(), codes, chars);
            for (int code : codes) {
                assertEquals(binding.action(), KeyBindings.forKeyCode(code),
                        "'" + row.keys() + "': " + KeyEvent.getKeyText(code) + " pressed");
            }
            for (char c : chars) {
                assertEquals(binding.action(), KeyBindings.forChar(c), "'" + row.keys() + "': " + c + " typed");
            }
            // and the other way: every key the program binds to this action is named in its row
            assertEquals(new HashSet<>(binding.keyCodes()), codes, "'" + row.keys() + "': the codes bound");
            Set<Character> bound = new HashSet<>();
            for (char c : binding.chars().toCharArray()) {
                bound.add(c);
            }
            assertEquals(bound, chars, "'" + row.keys() + "': the characters bound");
        }
    }

    @Test
    void theExposureAndToneKeysAreBound() throws IOException {
        assertEquals(Action.EXPOSURE_UP, KeyBindings.forChar('.'));
        assertEquals(Action.EXPOSURE_DOWN, KeyBindings.forChar(','));
        assertEquals(Action.TOGGLE_TONE, KeyBindings.forKeyCode(KeyEvent.VK_T));
        assertFalse(documentedRows().isEmpty());
        assertTrue(documentedRows().stream().anyMatch(r -> r.keys().equals("T")));
    }
}
