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
        StringBuilder sb = new StringBuilder(file);
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

    /** What the user wrote, in quotes, cut to its first 60 characters: {@code 'text'} or {@code 'text...'}. */
    public static String quote(String text) {
        int cut = 60;
        if (text.length() <= cut) {
            return "'" + text + "'";
        }
        if (Character.isHighSurrogate(text.charAt(cut - 1))) {
            cut--;
        }
        return "'" + text.substring(0, cut) + "...'";
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
