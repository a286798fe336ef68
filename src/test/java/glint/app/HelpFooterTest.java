package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.ui.input.KeyBindings;
import java.io.PrintWriter;
import java.io.StringWriter;
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
