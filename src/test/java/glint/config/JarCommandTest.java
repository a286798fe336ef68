package glint.config;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The jar a suggested command names, as a shell reads it back. */
class JarCommandTest {

    @Test
    void aJarInsideTheWorkingFolderIsNamedRelativeToIt() {
        assertEquals(Path.of("target/glint.jar"), JarCommand.shown(Path.of("/home/me/glint/target/glint.jar"),
                Path.of("/home/me/glint")));
        assertEquals(Path.of("glint.jar"), JarCommand.shown(Path.of("/home/me/lib/../glint.jar"), Path.of("/home/me")));
    }

    @Test
    void aJarElsewhereIsNamedByItsAbsolutePath() {
        assertEquals(Path.of("/opt/glint/glint.jar"), JarCommand.shown(Path.of("/opt/glint/glint.jar"), Path.of("/home/me")));
        // a folder that only begins like the working folder's name is not inside it
        assertEquals(Path.of("/home/me2/glint.jar"), JarCommand.shown(Path.of("/home/me2/glint.jar"), Path.of("/home/me")));
    }

    @Test
    void runFromItsClassesTheProgramNamesTheBuildsJar() {
        // the tests run from target/classes, not a jar
        assertEquals(Path.of("target/glint.jar"), JarCommand.runningJar());
        assertEquals("java -jar target/glint.jar", JarCommand.java());
    }

    @Test
    void aWordAShellWouldSplitOrExpandIsQuoted() {
        assertEquals("target/glint.jar", JarCommand.word("target/glint.jar"));
        assertEquals("\"/home/me/my jars/glint.jar\"", JarCommand.word("/home/me/my jars/glint.jar"));
        assertEquals("\"a\\\"b\\$c\\`d\\\\e\"", JarCommand.word("a\"b$c`d\\e"));
        assertEquals("\"it's.yaml\"", JarCommand.word("it's.yaml"));
    }

    /** A line break or a terminal's escape in a word: one printable line that bash reads back as the same bytes. */
    @Test
    void aWordWithAControlCharacterIsWrittenAsBashReadsItBack() throws Exception {
        assertEquals("$'a\\nb.yaml'", JarCommand.word("a\nb.yaml"));
        assertEquals("$'it\\'s\\u001b[2J \\\\.yaml'", JarCommand.word("it's\u001b[2J \\.yaml"));
        java.io.File bash = new java.io.File("/bin/bash");
        org.junit.jupiter.api.Assumptions.assumeTrue(bash.canExecute(), "bash is here");
        for (String word : new String[] {"a\nb.yaml", "it's\u001b[2J \\.yaml", "tab\there\r\u0007$x`y\"z"}) {
            Process p = new ProcessBuilder("/bin/bash", "-c", "printf %s " + JarCommand.word(word)).start();
            String read = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
            assertEquals(0, p.waitFor());
            assertEquals(word, read, JarCommand.word(word));
        }
    }
}
