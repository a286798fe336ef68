package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Mistyped options and stray words: each named, with the option meant, and status 2. */
class UnknownArgumentsTest {

    private static final String TRY = "Try 'java -jar target/glint.jar --help' for the options.";

    /** Runs the program and returns what it wrote on standard error, after checking its status and output. */
    private static String errOf(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = Main.run(args, new PrintWriter(out, true), new PrintWriter(err, true));
        assertEquals(Main.BAD_INPUT, status, err::toString);
        assertEquals("", out.toString());
        return err.toString();
    }

    private static String lines(String... lines) {
        return String.join(System.lineSeparator(), lines) + System.lineSeparator();
    }

    /** An argument beginning with @ is a word like any other, never a file read as more arguments. */
    @Test
    void anAtSignIsNotAFileOfArguments(@TempDir Path dir) throws IOException {
        Path args = Files.writeString(dir.resolve("args"), "--version\n");
        assertEquals(lines("glint: unexpected argument '@" + args + "' (each value follows its option, as in --spp 4)", TRY),
                errOf("@" + args));
    }

    @Test
    void aMistypedOptionIsNamedWithTheOneMeantAndItsValueIsNotCalledAnOption() {
        assertEquals(lines("glint: unknown option '--sppp'; did you mean '--spp'?", TRY), errOf("--sppp", "4"));
    }

    @Test
    void aLongOptionWrittenWithOneDashIsTheLongOption() {
        assertEquals(lines("glint: unknown option '-scene'; did you mean '--scene'?", TRY), errOf("-scene", "x"));
    }

    @Test
    void anOptionInCapitalsIsTheOptionInSmallLetters() {
        assertEquals(lines("glint: unknown option '--Scene'; did you mean '--scene'?", TRY),
                errOf("--Scene", "a.yaml"));
    }

    @Test
    void anOptionWithItsValueAfterAnEqualsSignIsNamedWithoutTheValue() {
        assertEquals(lines("glint: unknown option '--sppp'; did you mean '--spp'?", TRY), errOf("--sppp=4"));
    }

    @Test
    void aNegativeValueAfterAMistypedOptionIsItsValue() {
        assertEquals(lines("glint: unknown option '--dpth'; did you mean '--depth'?", TRY), errOf("--dpth", "-5"));
    }

    @Test
    void everyMistypedOptionIsNamed() {
        assertEquals(lines("glint: unknown option '--sppp'; did you mean '--spp'?",
                "glint: unknown option '--dpth'; did you mean '--depth'?", TRY),
                errOf("--sppp", "4", "--dpth", "3", "--width", "10"));
    }

    @Test
    void anOptionLikeNoneIsNamedAlone() {
        assertEquals(lines("glint: unknown option '--bogus'", TRY), errOf("--bogus"));
    }

    @Test
    void aSceneFileWithoutItsOptionIsShownWithIt() {
        assertEquals(lines("glint: unexpected argument 'scenes/glass.yaml'; did you mean '--scene scenes/glass.yaml'?",
                TRY), errOf("scenes/glass.yaml"));
    }

    @Test
    void aStrayWordSaysThatValuesFollowTheirOptions() {
        assertEquals(lines("glint: unexpected argument 'extra' (each value follows its option, as in --spp 4)", TRY),
                errOf("--spp", "4", "extra"));
    }
}
