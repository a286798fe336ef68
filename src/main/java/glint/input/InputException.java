package glint.input;

/**
 * Bad user input (scene, config or arguments) at a known place. Its message is what the user
 * sees: {@code file:line:column: what is wrong}. Lines and columns count from 1; 0 means unknown.
 */
public final class InputException extends Exception {

    private final String file;
    private final int line;
    private final int column;
    private final String problem;

    public InputException(String file, int line, int column, String problem) {
        super(format(file, line, column, problem), null, false, false);
        this.file = file;
        this.line = line;
        this.column = column;
        this.problem = problem;
    }

    private static String format(String file, int line, int column, String problem) {
        StringBuilder sb = new StringBuilder(cutPath(file));
        if (line > 0) {
            sb.append(':').append(line);
            if (column > 0) {
                sb.append(':').append(column);
            }
        }
        return printable(sb.append(": ").append(problem).toString());
    }

    /**
     * The text with every character that could move the cursor or change the terminal (line breaks,
     * escape sequences, other control and bidirectional-override characters) written as an escape
     * such as {@code \n} or {@code \u001b}: a message is always one line and prints as it reads.
     */
    public static String printable(String text) {
        StringBuilder sb = null;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            String escape = c == '\n' ? "\\n" : c == '\r' ? "\\r" : c == '\t' ? "\\t"
                    : isControl(c) ? String.format("\\u%04x", (int) c) : null;
            if (escape != null && sb == null) {
                sb = new StringBuilder(text.length() + 16).append(text, 0, i);
            }
            if (sb != null) {
                if (escape != null) {
                    sb.append(escape);
                } else {
                    sb.append(c);
                }
            }
        }
        return sb == null ? text : sb.toString();
    }

    private static boolean isControl(char c) {
        return c < 0x20 || (c >= 0x7f && c < 0xa0) || (c >= 0x202a && c <= 0x202e) || (c >= 0x2066 && c <= 0x2069)
                || c == 0x200e || c == 0x200f || c == 0x2028 || c == 0x2029;
    }

    /** The most characters of a value the user wrote that a message shows. */
    public static final int MAX_QUOTED = 60;
    /** The most characters of a file name a message shows: its first and last 60. */
    public static final int MAX_PATH = 2 * MAX_QUOTED;

    /** What the user wrote, in quotes, cut to its first 60 characters: {@code 'text'} or {@code 'text...'}. */
    public static String quote(String text) {
        return "'" + cut(text) + "'";
    }

    /** What the user wrote, cut to its first 60 characters (code points): {@code text} or {@code text...}. */
    public static String cut(String text) {
        return text.codePointCount(0, text.length()) > MAX_QUOTED ? head(text, MAX_QUOTED) + "..." : text;
    }

    /**
     * A number for a message that says it is beyond {@code limit}: with {@code digits} significant
     * digits, or as many more as it takes to read differently from the limit (1.0000001e30 is not
     * shown as 1.00e+30 beside a limit of 1e30).
     */
    public static String beyond(double value, double limit, int digits) {
        for (int d = digits; ; d++) {
            String shown = String.format(java.util.Locale.ROOT, "%." + d + "g", value);
            if (d >= 17 || !shown.equals(String.format(java.util.Locale.ROOT, "%." + d + "g", limit))) {
                return shown;
            }
        }
    }

    /**
     * A file name for a message: as it is up to 120 characters, else its first and last 60 around
     * {@code ...} (the end names the file, the start where it is).
     */
    public static String cutPath(String path) {
        int length = path.codePointCount(0, path.length());
        if (length <= MAX_PATH) {
            return path;
        }
        return head(path, MAX_QUOTED) + "..." + path.substring(path.offsetByCodePoints(0, length - MAX_QUOTED));
    }

    /** A file name in quotes, cut as by {@link #cutPath}. */
    public static String quotePath(Object path) {
        return "'" + cutPath(String.valueOf(path)) + "'";
    }

    /**
     * The message with every quoted part longer than 60 characters cut as by {@link #quote}: for
     * messages made elsewhere (the argument parser's) that echo what the user typed.
     */
    public static String cutQuoted(String message) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("'([^']{" + (MAX_QUOTED + 1) + ",})'").matcher(message);
        StringBuilder sb = new StringBuilder();
        while (m.find()) {
            m.appendReplacement(sb, java.util.regex.Matcher.quoteReplacement(quote(m.group(1))));
        }
        return m.appendTail(sb).toString();
    }

    /**
     * The message with every word (a run without spaces) longer than 60 characters cut as by
     * {@link #cut}: for messages made elsewhere (the YAML reader's) that echo a name the user wrote.
     */
    public static String cutLongWords(String message) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\\S{" + (MAX_QUOTED + 1) + ",}").matcher(message);
        StringBuilder sb = new StringBuilder();
        while (m.find()) {
            m.appendReplacement(sb, java.util.regex.Matcher.quoteReplacement(cut(m.group())));
        }
        return m.appendTail(sb).toString();
    }

    /** The first {@code max} characters (code points) of the text. */
    private static String head(String text, int max) {
        if (text.codePointCount(0, text.length()) <= max) {
            return text;
        }
        return text.substring(0, text.offsetByCodePoints(0, max));
    }

    public String file() {
        return file;
    }

    public int line() {
        return line;
    }

    public int column() {
        return column;
    }

    /** The message without its position. */
    public String problem() {
        return problem;
    }
}
