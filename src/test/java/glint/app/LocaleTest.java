package glint.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * File names that are not ASCII, in a real process under a POSIX locale (LC_ALL=C, as cron,
 * minimal containers and CI run): Java 17 cannot carry them there, so each is refused in one line
 * that names the locale and how to change it, with status 2 and no Java class name; under
 * LC_ALL=C.UTF-8 the same names work. The script's bytes reach the program as written, whatever
 * this JVM's own locale.
 */
class LocaleTest {

    private static final String SCENE = "camera: {position: [0, 1, -4], look_at: [0, 1, 0]}\n"
            + "objects:\n  - {type: sphere, center: [0, 1, 0], radius: 1}\n";
    private static final String FIX = "use a UTF-8 locale, for example: export LC_ALL=C.UTF-8";

    @TempDir
    Path dir;

    private static boolean hasUtf8Locale() throws Exception {
        try {
            Process locales = new ProcessBuilder("locale", "-a").redirectErrorStream(true).start();
            String all = new String(locales.getInputStream().readAllBytes(), StandardCharsets.ISO_8859_1).toLowerCase();
            return locales.waitFor() != 0 || all.contains("c.utf8") || all.contains("c.utf-8");
        } catch (java.io.IOException e) {
            return true; // no locale command: try
        }
    }

    /**
     * A script that makes the files (names in UTF-8), then runs the program with the arguments
     * under the locale (none at all for null).
     */
    private Child.Result run(String locale, String... args) throws Exception {
        Files.writeString(dir.resolve("scene.yaml"), SCENE);
        Files.writeString(dir.resolve("empty.properties"), "");
        List<String> command = new ArrayList<>(Child.java());
        command.addAll(List.of(args));
        command.addAll(List.of("--width", "8", "--height", "6", "--spp", "1", "--threads", "1"));
        String script = (locale == null ? "unset LC_ALL LC_CTYPE LANG\n" : "")
                + "cp scene.yaml 'café.yaml'\n"
                + "printf 'scene=café.yaml\\n' > scene-cafe.properties\n"
                + Child.line(command) + "\n"
                + "status=$?\n"
                + "for f in *.png; do [ -e \"$f\" ] && echo \"present: $f\"; done\n"
                + "ls -a | grep -c part\n" // temporary files left: 0
                + "exit $status\n";
        Child.Result r = Child.sh(dir, script, locale == null ? Map.of() : Map.of("LC_ALL", locale));
        assertFalse(r.err().contains("java.") || r.err().contains("Exception"), r.err());
        return r;
    }

    @Test
    void aSceneNameThatIsNotAsciiIsRefusedUnderThePosixLocale() throws Exception {
        Child.Result r = run("C", "--config", "empty.properties", "--scene", "café.yaml", "--output", "out.png");
        assertEquals(2, r.status());
        assertEquals("glint: Invalid value for option '--scene': the file name 'caf??.yaml' is not ASCII, and the locale "
                + "(LC_ALL=C) allows only ASCII file names; " + FIX + "\n", r.err());
        assertEquals("0\n", r.out(), "no image, no temporary file");
    }

    @Test
    void anOutputNameThatIsNotAsciiIsRefusedUnderThePosixLocale() throws Exception {
        Child.Result r = run("C", "--config", "empty.properties", "--scene", "scene.yaml", "--output", "été.png");
        assertEquals(2, r.status());
        assertEquals("glint: Invalid value for option '--output': the file name '??t??.png' is not ASCII, and the locale "
                + "(LC_ALL=C) allows only ASCII file names; " + FIX + "\n", r.err());
        assertEquals("0\n", r.out());
    }

    @Test
    void aConfiguredSceneThatIsNotAsciiIsRefusedAtItsLineUnderThePosixLocale() throws Exception {
        Child.Result r = run("C", "--config", "scene-cafe.properties", "--output", "out.png");
        assertEquals(2, r.status());
        assertEquals("scene-cafe.properties:1:1: scene: the file name 'caf\\u00e9.yaml' is not ASCII, and the locale "
                + "(LC_ALL=C) allows only ASCII file names; " + FIX + "\n", r.err());
    }

    @Test
    void withNoLocaleSetTheMessageSaysSo() throws Exception {
        Child.Result r = run(null, "--config", "empty.properties", "--scene", "café.yaml", "--output", "out.png");
        assertEquals(2, r.status());
        assertEquals("glint: Invalid value for option '--scene': the file name 'caf??.yaml' is not ASCII, and the locale "
                + "(none set, so POSIX) allows only ASCII file names; " + FIX + "\n", r.err());
    }

    @Test
    void theSameNamesWorkUnderAUtf8Locale() throws Exception {
        assumeTrue(hasUtf8Locale(), "no C.UTF-8 locale on this system");
        Child.Result r = run("C.UTF-8", "--config", "empty.properties", "--scene", "café.yaml", "--output", "été.png");
        assertEquals(0, r.status(), r.err());
        String out = new String(r.out().getBytes(StandardCharsets.ISO_8859_1), StandardCharsets.UTF_8);
        List<String> lines = out.lines().toList();
        assertEquals(3, lines.size(), out);
        assertTrue(lines.get(0).startsWith("wrote été.png (8x6, 1 spp, 1 threads, cook-torrance, depth 16) in "), out);
        assertEquals(List.of("present: été.png", "0"), lines.subList(1, 3));
    }

    /** A scene with a view named café, and the program run on it with {@code args} under the locale. */
    private Child.Result runOnViews(String locale, String... args) throws Exception {
        Files.writeString(dir.resolve("views.yaml"), SCENE + "views:\n  - {name: caf\u00e9, position: [0, 2, -4], "
                + "look_at: [0, 1, 0]}\n", StandardCharsets.UTF_8);
        Files.writeString(dir.resolve("empty.properties"), "");
        List<String> command = new ArrayList<>(Child.java());
        command.addAll(List.of("--config", "empty.properties", "--scene", "views.yaml", "--width", "8", "--height", "6",
                "--spp", "1", "--threads", "1"));
        command.addAll(List.of(args));
        Child.Result r = Child.sh(dir, Child.line(command) + "\n", Map.of("LC_ALL", locale));
        assertFalse(r.err().contains("java.") || r.err().contains("Exception"), r.err());
        return r;
    }

    private static final String NOTE = "glint: characters the locale (LC_ALL=C) cannot show are written as \\uXXXX, their "
            + "Unicode code; " + FIX + "\n";

    /** Under LC_ALL=C a suggestion that is not ASCII is written as its code, said once, never as a 'caf?' to type. */
    @Test
    void aSuggestionTheLocaleCannotShowIsWrittenAsItsCodeAndSaidOnce() throws Exception {
        Child.Result r = runOnViews("C", "--view", "cafe", "--output", "out.png");
        assertEquals(2, r.status());
        assertEquals("glint: --view 'cafe': 'views.yaml' has no view of that name (did you mean 'caf\\u00e9'?)\n"
                + NOTE, r.err());
        assertFalse(Files.exists(dir.resolve("out.png")));
    }

    /** Standard output too: --bench names the view by its code, and standard error says why, once. */
    @Test
    void aViewsNameOnStandardOutputIsWrittenAsItsCodeUnderThePosixLocale() throws Exception {
        Child.Result r = runOnViews("C", "--view", "1", "--bench", "2");
        assertEquals(0, r.status(), r.err());
        assertEquals("timing 2 frames of views.yaml, view 1 'caf\\u00e9' (8x6, 1 spp, 1 threads, cook-torrance, depth 16)",
                r.out().lines().findFirst().orElse(""));
        assertEquals(NOTE, r.err());
    }

    /** Typed under LC_ALL=C, café arrives without its bytes: the message names the locale. */
    @Test
    void aViewNameTypedThatIsNotAsciiIsRefusedNamingThePosixLocale() throws Exception {
        Child.Result r = runOnViews("C", "--view", "caf\u00e9", "--output", "out.png");
        assertEquals(2, r.status());
        assertEquals("glint: --view 'caf??': the name is not ASCII, and the locale (LC_ALL=C) allows only ASCII "
                + "arguments; " + FIX + "\n", r.err());
    }

    @Test
    void aViewNameThatIsNotAsciiWorksUnderAUtf8Locale() throws Exception {
        assumeTrue(hasUtf8Locale(), "no C.UTF-8 locale on this system");
        Child.Result r = runOnViews("C.UTF-8", "--view", "caf\u00e9", "--bench", "1");
        assertEquals(0, r.status(), r.err());
        String out = new String(r.out().getBytes(StandardCharsets.ISO_8859_1), StandardCharsets.UTF_8);
        assertTrue(out.startsWith("timing 1 frame of views.yaml, view 1 'caf\u00e9' ("), out);
        assertEquals("", r.err());
    }
}
