package glint.app;

import glint.config.JarCommand;
import glint.ui.input.KeyBindings;
import java.util.ArrayList;
import java.util.List;

/**
 * The end of {@code --help}: a few example commands and the window's keys (from {@link KeyBindings}). Its lines
 * are printed as they are, not wrapped by the parser (which breaks a line at the 80th column, in the middle
 * of a word): a command wider than {@link #WIDTH} is broken between its words, with a shell's {@code \} at
 * the end of each line but the last, so that it can still be pasted whole.
 */
final class HelpFooter {

    /** The columns a line of the footer keeps within, as the parser's usage text does. */
    static final int WIDTH = 80;
    private static final String COMMAND_INDENT = "    ";
    private static final String CONTINUED_INDENT = "      ";

    private HelpFooter() {
    }

    /** The footer's lines, with the jar this program runs from. */
    static List<String> lines() {
        return lines(JarCommand.java());
    }

    /** The footer's lines, the commands starting with {@code jar} ({@code java -jar target/glint.jar}). */
    static List<String> lines(String jar) {
        List<String> lines = new ArrayList<>();
        lines.add("");
        lines.add("Examples:");
        lines.add("  Open the window on the config's scene, or on another one:");
        command(lines, jar, "");
        command(lines, jar, "--scene scenes/glass.yaml");
        lines.add("  Render a still to a file, or one of the scene's views; time 10 frames:");
        command(lines, jar, "--scene scenes/metals.yaml --output metals.png");
        command(lines, jar, "--scene scenes/field.yaml --view 2 --output a.png");
        command(lines, jar, "--scene scenes/field.yaml --bench 10");
        lines.add("  Which integrator: whitted (the default) is quick and clean while you fly");
        lines.add("  in the window; path (light that bounces, the sky lights the scene) is for");
        lines.add("  stills, at 64 samples a pixel or more:");
        command(lines, jar, "--integrator path --spp 64 --output bounce.png");
        lines.add("  A stop brighter (PNGs and the window; a PFM keeps the linear values):");
        command(lines, jar, "--exposure 1 --output brighter.png");
        lines.add("  Settings rank: a flag, then the scene's render: block, then the config.");
        lines.add("");
        lines.add("Window keys (Enter renders the view as a still; the window goes on):");
        for (String help : KeyBindings.helpLines()) {
            lines.add("  " + help);
        }
        return lines;
    }

    /**
     * Adds {@code jar args} as one line, or, wider than {@link #WIDTH}, as lines broken between words, each but
     * the last ending in {@code " \"}; a word wider than a line stands alone on its own, whole.
     */
    static void command(List<String> lines, String jar, String args) {
        String text = args.isEmpty() ? jar : jar + " " + args;
        if (COMMAND_INDENT.length() + text.length() <= WIDTH) {
            lines.add(COMMAND_INDENT + text);
            return;
        }
        StringBuilder line = new StringBuilder(COMMAND_INDENT);
        boolean empty = true;
        for (String word : words(text)) {
            if (!empty && line.length() + 1 + word.length() + 2 > WIDTH) {
                lines.add(line.append(" \\").toString());
                line = new StringBuilder(CONTINUED_INDENT);
                empty = true;
            }
            if (!empty) {
                line.append(' ');
            }
            line.append(word);
            empty = false;
        }
        lines.add(line.toString());
    }

    /**
     * The words of a command: split at spaces, but a double-quoted word ({@link JarCommand#word}, a jar path
     * with a space) kept whole.
     */
    private static List<String> words(String text) {
        List<String> words = new ArrayList<>();
        StringBuilder word = new StringBuilder();
        boolean quoted = false;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '\\' && quoted && i + 1 < text.length()) {
                word.append(c).append(text.charAt(++i));
                continue;
            }
            if (c == '"') {
                quoted = !quoted;
            }
            if (c == ' ' && !quoted) {
                if (word.length() > 0) {
                    words.add(word.toString());
                    word.setLength(0);
                }
                continue;
            }
            word.append(c);
        }
        if (word.length() > 0) {
            words.add(word.toString());
        }
        return words;
    }

    /** The footer as printed: its lines, each ending in a line break. */
    static String text() {
        StringBuilder sb = new StringBuilder();
        for (String line : lines()) {
            sb.append(line).append(System.lineSeparator());
        }
        return sb.toString();
    }
}
