package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The progress bar follows standard error, and what is said while it is drawn starts a line of its own. */
class ProgressLineTest {

    @TempDir
    Path dir;

    /** Standard error sent to a file gets plain lines, whatever standard input and output are (a terminal here). */
    @Test
    void standardErrorInAFileIsNoTerminalAndAPseudoTerminalIsOne() throws IOException {
        Path log = Files.createFile(dir.resolve("log.txt"));
        assertFalse(Progress.isTerminal(Files.createSymbolicLink(dir.resolve("fd2"), log), true));
        assertTrue(Progress.isTerminal(Files.createSymbolicLink(dir.resolve("pts"), Path.of("/dev/pts/3")), false));
        assertTrue(Progress.isTerminal(dir.resolve("no such link"), true), "where it cannot be told: the console");
    }

    /** "glint: interrupted" while the bar is drawn: the bar is cleared first, the line is not appended to it. */
    @Test
    void theInterruptedLineIsNeverOnTheBarsLine() {
        StringWriter text = new StringWriter();
        PrintWriter err = new PrintWriter(text, true);
        long[] now = {0};
        Progress progress = Progress.onTerminal(err, () -> now[0]);
        progress.step("rendering", () -> 0.5);
        now[0] = 3_000_000_000L;
        progress.show();
        assertTrue(text.toString().startsWith("\rrendering ["), text.toString());
        try (Interrupts interrupts = Interrupts.install(err, Headless.INTERRUPTED_STILL)) {
            interrupts.clearLineWith(progress::close);
            interrupts.report(Headless.INTERRUPTED_STILL);
        }
        String said = text.toString();
        assertTrue(said.endsWith("\r" + " ".repeat(90) + "\r" + Headless.INTERRUPTED_STILL + System.lineSeparator()),
                said);
        assertEquals(1, said.lines().filter(l -> l.contains("interrupted")).count());
    }
}
