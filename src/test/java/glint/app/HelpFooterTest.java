package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.ui.input.KeyBindings;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** {@code --help} ends with example commands and every key of the window. */
class HelpFooterTest {

    @Test
    void helpListsEveryKeyAndExamples() {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        assertEquals(Main.OK, Main.run(new String[] {"--help"}, new PrintWriter(out, true), new PrintWriter(err, true)));
        String help = out.toString();
        assertTrue(help.contains("Examples:"), help);
        assertTrue(help.contains("java -jar target/glint.jar --scene scenes/glass.yaml"), help);
        for (String line : KeyBindings.helpLines()) {
            assertTrue(help.contains("  " + line + System.lineSeparator()), "missing: " + line + "\n" + help);
        }
        assertEquals("", err.toString());
        for (String line : HelpFooter.lines()) {
            // wider lines picocli would break wherever the 80th column falls
            assertTrue(line.length() <= 80, "wider than the terminal picocli assumes: " + line);
        }
    }

    /** A long jar path: commands broken between words with a shell's backslash, never in a word; pasted whole. */
    @Test
    void aLongJarPathBreaksCommandsBetweenWordsNeverInAWord() {
        String jar = "java -jar \"/home/someone/projects/a long folder name/that goes on and on/target/glint.jar\"";
        List<String> lines = HelpFooter.lines(jar);
        List<String> commands = new ArrayList<>();
        StringBuilder command = null;
        for (String line : lines) {
            if (line.startsWith("    java -jar")) {
                command = new StringBuilder(line.strip());
            } else if (command != null && line.startsWith("      ")) {
                command.append(' ').append(line.strip());
            }
            if (command != null && !command.toString().endsWith("\\")) {
                commands.add(command.toString());
                command = null;
            } else if (command != null) {
                command.setLength(command.length() - 2);
            }
            String word = line.strip();
            assertTrue(line.length() <= HelpFooter.WIDTH || !word.contains(" ") || word.startsWith("\""),
                    "wider than the terminal, and not one word: " + line);
        }
        assertTrue(commands.contains(jar + " --scene scenes/metals.yaml --output metals.png"), commands::toString);
        assertTrue(commands.contains(jar), commands::toString);
        assertEquals(7, commands.size(), commands::toString);
        assertTrue(lines.contains("      --scene scenes/metals.yaml --output metals.png"), lines::toString);
        assertTrue(lines.contains("      \"/home/someone/projects/a long folder name/that goes on and on/target/glint.jar\" \\"),
                lines::toString);
    }

    /** The parser prints the footer as it is: a line of 80 columns is not broken again. */
    @Test
    void theHelpPrintsTheFooterUnwrapped() {
        StringWriter out = new StringWriter();
        Main.run(new String[] {"--help"}, new PrintWriter(out, true), new PrintWriter(new StringWriter(), true));
        assertTrue(out.toString().endsWith(HelpFooter.text()), out::toString);
    }

    @Test
    void theExampleScenesExist() {
        for (String line : HelpFooter.lines()) {
            int at = line.indexOf("scenes/");
            if (at >= 0) {
                String file = line.substring(at, line.indexOf(".yaml", at) + 5);
                assertTrue(java.nio.file.Files.isRegularFile(java.nio.file.Path.of(file)), file);
            }
        }
    }
}
