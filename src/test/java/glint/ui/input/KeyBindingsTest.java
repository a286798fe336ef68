package glint.ui.input;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.KeyEvent;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** One table of controls: complete, unambiguous, and the same in docs/window.md. */
class KeyBindingsTest {

    @Test
    void everyActionHasExactlyOneRow() {
        Set<Action> seen = EnumSet.noneOf(Action.class);
        for (KeyBindings.Binding b : KeyBindings.ALL) {
            assertTrue(seen.add(b.action()), "two rows for " + b.action());
        }
        assertEquals(EnumSet.allOf(Action.class), seen);
    }

    @Test
    void noKeyDoesTwoThings() {
        Set<Integer> codes = new HashSet<>();
        Set<Character> chars = new HashSet<>();
        for (KeyBindings.Binding b : KeyBindings.ALL) {
            for (int code : b.keyCodes()) {
                assertTrue(codes.add(code), "key code " + KeyEvent.getKeyText(code) + " bound twice");
            }
            for (char c : b.chars().toCharArray()) {
                assertTrue(chars.add(c), "character " + c + " bound twice");
            }
            if (b.action().kind() == Action.Kind.POINTER) {
                assertTrue(b.keyCodes().isEmpty() && b.chars().isEmpty());
            } else {
                assertTrue(!b.keyCodes().isEmpty() || !b.chars().isEmpty() || b.keys().startsWith("Shift + ")
                        || b.meaning().startsWith("a still under way: "), "no key for " + b.action());
                // a Shift combination, and a key while the overlay says a still is under way, the listener tells apart
            }
        }
    }

    @Test
    void theSeedsKeysAndTheIssuesKeys() {
        assertEquals(Action.FORWARD, KeyBindings.forKeyCode(KeyEvent.VK_W));
        assertEquals(Action.BACK, KeyBindings.forKeyCode(KeyEvent.VK_S));
        assertEquals(Action.LEFT, KeyBindings.forKeyCode(KeyEvent.VK_A));
        assertEquals(Action.RIGHT, KeyBindings.forKeyCode(KeyEvent.VK_D));
        assertEquals(Action.UP, KeyBindings.forKeyCode(KeyEvent.VK_R));
        assertEquals(Action.DOWN, KeyBindings.forKeyCode(KeyEvent.VK_F));
        assertEquals(Action.YAW_LEFT, KeyBindings.forKeyCode(KeyEvent.VK_LEFT));
        assertEquals(Action.PITCH_UP, KeyBindings.forKeyCode(KeyEvent.VK_UP));
        assertEquals(Action.ROLL_LEFT, KeyBindings.forKeyCode(KeyEvent.VK_Q));
        assertEquals(Action.ROLL_RIGHT, KeyBindings.forKeyCode(KeyEvent.VK_E));
        assertEquals(Action.FAST, KeyBindings.forKeyCode(KeyEvent.VK_SHIFT));
        assertEquals(Action.SCREENSHOT, KeyBindings.forKeyCode(KeyEvent.VK_F12));
        assertEquals(Action.SCREENSHOT, KeyBindings.forKeyCode(KeyEvent.VK_P));
        assertEquals(Action.RELOAD, KeyBindings.forKeyCode(KeyEvent.VK_F5));
        assertEquals(Action.QUIT, KeyBindings.forKeyCode(KeyEvent.VK_ESCAPE));
        assertEquals(Action.TOGGLE_OVERLAY, KeyBindings.forKeyCode(KeyEvent.VK_H));
        assertEquals(Action.TOGGLE_SHADING, KeyBindings.forKeyCode(KeyEvent.VK_M));
        assertEquals(Action.DEPTH_UP, KeyBindings.forChar('+'));
        assertEquals(Action.DEPTH_DOWN, KeyBindings.forChar('-'));
        assertEquals(Action.TOGGLE_HELP, KeyBindings.forChar('?'));
        assertNull(KeyBindings.forKeyCode(KeyEvent.VK_J));
        assertNull(KeyBindings.forChar('w'));
    }

    @Test
    void helpHasALineForEveryRow() {
        assertEquals(KeyBindings.ALL.size(), KeyBindings.helpLines().size());
        assertTrue(KeyBindings.helpLines().get(0).startsWith("W "));
    }

    @Test
    void docsHoldTheSameTable() throws IOException {
        String docs = Files.readString(Path.of("docs/window.md"), StandardCharsets.UTF_8);
        assertTrue(docs.contains(KeyBindings.markdownTable()),
                "docs/window.md must contain the controls table exactly as KeyBindings.markdownTable():\n"
                        + KeyBindings.markdownTable());
    }
}
