package glint.config;

import glint.input.InputException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Pattern;

/**
 * The command that starts this program, for the commands its messages and reports suggest:
 * {@code java -jar} and the jar it runs from, as the user can type it again.
 */
public final class JarCommand {

    /** The jar of the build, named when the program does not run from a jar (from its classes). */
    static final Path BUILT_JAR = Path.of("target", "glint.jar");
    /** Words a shell takes as they are. */
    private static final Pattern PLAIN = Pattern.compile("[A-Za-z0-9_./+:,=@%-]+");

    private JarCommand() {
    }

    private static final class Holder {
        static final String JAVA = "java -jar " + word(shown(runningJar(), Path.of("").toAbsolutePath()).toString());
    }

    /** {@code java -jar target/glint.jar}, with the path of the jar this program runs from. */
    public static String java() {
        return Holder.JAVA;
    }

    /**
     * The jar this program runs from (its classes' code source, when that is a jar file), or
     * {@link #BUILT_JAR} when it runs from its classes or cannot tell.
     */
    static Path runningJar() {
        try {
            var source = JarCommand.class.getProtectionDomain().getCodeSource();
            Path path = source == null ? null : Path.of(source.getLocation().toURI());
            return path != null && Files.isRegularFile(path) ? path : BUILT_JAR;
        } catch (RuntimeException | java.net.URISyntaxException e) { // no file system path, or not allowed to ask
            return BUILT_JAR;
        }
    }

    /** The jar as a command names it: relative to the working folder when inside it, else as it is (absolute). */
    static Path shown(Path jar, Path workingFolder) {
        if (!jar.isAbsolute()) {
            return jar;
        }
        Path normal = jar.normalize();
        return normal.startsWith(workingFolder) && !normal.equals(workingFolder) ? workingFolder.relativize(normal) : normal;
    }

    /**
     * A word of a command as a POSIX shell reads it back: as it is when plain, otherwise in double
     * quotes, with {@code \ " $ `} escaped ({@code "/home/me/my jars/glint.jar"}); one with a line break or
     * another control character as bash's {@code $'...'} with escapes ({@code $'a\nb.yaml'}), so the command is
     * one line that prints as it reads.
     */
    public static String word(String text) {
        if (PLAIN.matcher(text).matches()) {
            return text;
        }
        String escaped = text.replace("\\", "\\\\").replace("'", "\\'");
        if (!InputException.printable(escaped).equals(escaped)) { // a line break, a terminal's escape: as bash reads them
            return "$'" + InputException.printable(escaped) + "'";
        }
        return '"' + text.replaceAll("([\\\\\"$`])", "\\\\$1") + '"';
    }
}
