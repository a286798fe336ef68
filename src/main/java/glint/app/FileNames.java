package glint.app;

import glint.input.InputException;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.List;

/**
 * File names that are not ASCII under a POSIX locale ({@code LC_ALL=C}: cron, minimal containers,
 * CI). There Java 17 decodes the arguments as ASCII ({@code café.yaml} arrives as
 * {@code caf??.yaml}, the bytes lost) and can encode only ASCII file names; the setting behind it,
 * {@code sun.jnu.encoding}, is fixed by the JVM from the locale at startup (a {@code -D} on the
 * command line is overridden, and loading the program's jar already uses it). Such a name is
 * therefore refused in one line that names the locale and how to change it; under a UTF-8 locale
 * ({@code LC_ALL=C.UTF-8}) it works.
 */
final class FileNames {

    /** How to change the locale, the end of every message about it. */
    static final String FIX = "use a UTF-8 locale, for example: export LC_ALL=C.UTF-8";

    /** The replacement character Java puts for each byte it could not decode. */
    private static final char UNDECODED = '\uFFFD';

    private FileNames() {
    }

    /** Whether file names are ASCII only (the locale is the POSIX one). */
    static boolean asciiLocale() {
        try {
            String charset = System.getProperty("sun.jnu.encoding");
            return charset != null && Charset.forName(charset).equals(StandardCharsets.US_ASCII);
        } catch (IllegalArgumentException e) {
            return false;
        }
    }

    /**
     * A file name given by the user as a path, or an error that says which locale is in the way and
     * how to change it.
     */
    static Path path(String name) throws InvalidNameException {
        if (name.indexOf(UNDECODED) >= 0 && asciiLocale()) {
            throw new InvalidNameException(localeProblem(name));
        }
        try {
            return Path.of(name);
        } catch (InvalidPathException e) {
            throw new InvalidNameException(name.indexOf('\0') >= 0
                    ? "a file name cannot hold the character NUL, got " + InputException.quotePath(name)
                    : localeProblem(name));
        }
    }

    /**
     * Why a file name typed with a slash at its end is refused, or null ({@code new.png/}), which names a folder: as
     * {@code cp}, {@code tee} and the shell's {@code >} refuse it, and not, as the path it would
     * become, the file {@code new.png}. A folder of that name is left to the checks that say it is one.
     */
    static String folderNameProblem(String typed) {
        if (!typed.endsWith("/") || Files.isDirectory(Path.of(typed))) {
            return null;
        }
        String name = typed.replaceFirst("/+$", "");
        return InputException.quotePath(typed) + " ends in '/', so it names a folder, and "
                + (Files.exists(Path.of(name)) ? InputException.quotePath(name) + " is a file"
                        : "there is no folder " + InputException.quotePath(name))
                + "; write the file name without the '/'";
    }

    /** A name that cannot be a file name here; the message says why in words. */
    static final class InvalidNameException extends Exception {
        InvalidNameException(String message) {
            super(message, null, false, false);
        }
    }

    /** The one line for a name the locale cannot carry (or, under another locale, the system refuses). */
    static String localeProblem(String name) {
        if (!asciiLocale()) {
            return "the file name " + InputException.quotePath(name) + " cannot be used here: it has characters the locale ("
                    + locale() + ") cannot encode; " + FIX;
        }
        return "the file name " + InputException.quotePath(name) + " is not ASCII, and the locale (" + locale()
                + ") allows only ASCII file names; " + FIX;
    }

    /** The locale setting in force, as the user would write it: {@code LC_ALL=C}, or that none is set. */
    static String locale() {
        for (String variable : List.of("LC_ALL", "LC_CTYPE", "LANG")) {
            String value = System.getenv(variable);
            if (value != null && !value.isEmpty()) {
                return variable + "=" + InputException.cut(value);
            }
        }
        return "none set, so POSIX";
    }
}
