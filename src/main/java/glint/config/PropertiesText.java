package glint.config;

import glint.input.InputException;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The syntax of {@code java.util.Properties} (comments, {@code key=value}, {@code key: value},
 * {@code key value}, lines continued with a backslash, escapes such as {@code \u00e9}), read so that
 * every key keeps the line and column where it starts, however it is written.
 */
final class PropertiesText {

    /** A key's value and where the key stands (line and column from 1). */
    record Entry(String value, int line, int column) {
    }

    private final String file;
    private final String text;
    private int pos;
    private int line = 1;
    private int lineStart;

    /** A UTF-8 byte-order mark, which some editors put before the first line. */
    private static final char BYTE_ORDER_MARK = '\uFEFF';

    private PropertiesText(String file, String text) {
        this.file = file;
        this.text = text;
        if (!text.isEmpty() && text.charAt(0) == BYTE_ORDER_MARK) { // not part of the first key
            pos = 1;
            lineStart = 1;
        }
    }

    /** Every key with its last value and the position of the line that set it last. */
    static Map<String, Entry> parse(String file, String text) throws InputException {
        return new PropertiesText(file, text).entries();
    }

    private Map<String, Entry> entries() throws InputException {
        Map<String, Entry> entries = new LinkedHashMap<>();
        while (pos < text.length()) {
            skipWhitespace();
            if (pos >= text.length()) {
                break;
            }
            char c = text.charAt(pos);
            if (isLineBreak(c)) {
                newLine();
                continue;
            }
            if (c == '#' || c == '!') {
                while (pos < text.length() && !isLineBreak(text.charAt(pos))) {
                    pos++;
                }
                continue;
            }
            int keyLine = line, keyColumn = column(pos);
            String key = token(true);
            skipWhitespace();
            if (pos < text.length() && (text.charAt(pos) == '=' || text.charAt(pos) == ':')) {
                pos++;
                skipWhitespace();
            }
            String value = token(false);
            entries.remove(key); // the last setting counts, in the order of the file
            entries.put(key, new Entry(value, keyLine, keyColumn));
        }
        return entries;
    }

    /** A key (ends at = : or whitespace) or a value (ends at the end of the logical line), unescaped. */
    private String token(boolean key) throws InputException {
        StringBuilder sb = new StringBuilder();
        while (pos < text.length()) {
            char c = text.charAt(pos);
            if (isLineBreak(c) || (key && (c == '=' || c == ':' || c == ' ' || c == '\t' || c == '\f'))) {
                break;
            }
            pos++;
            if (c != '\\') {
                sb.append(c);
                continue;
            }
            if (pos >= text.length()) {
                break; // a backslash at the very end continues nothing
            }
            char e = text.charAt(pos);
            if (isLineBreak(e)) { // continuation: the next line's leading whitespace is skipped
                newLine();
                skipWhitespace();
                continue;
            }
            pos++;
            switch (e) {
                case 't' -> sb.append('\t');
                case 'n' -> sb.append('\n');
                case 'r' -> sb.append('\r');
                case 'f' -> sb.append('\f');
                case 'u' -> sb.append(unicode());
                default -> sb.append(e);
            }
        }
        return sb.toString();
    }

    private char unicode() throws InputException {
        int start = pos - 2;
        if (pos + 4 <= text.length()) {
            String hex = text.substring(pos, pos + 4);
            if (hex.chars().allMatch(h -> Character.digit(h, 16) >= 0 && h < 128)) {
                pos += 4;
                return (char) Integer.parseInt(hex, 16);
            }
        }
        throw new InputException(file, line, column(start),
                "a \\u escape needs four hex digits, as in \\u00e9");
    }

    /** The column (from 1, in characters: an emoji is one) of index {@code at} of the current line. */
    private int column(int at) {
        return text.codePointCount(lineStart, at) + 1;
    }

    private void newLine() {
        if (text.charAt(pos) == '\r' && pos + 1 < text.length() && text.charAt(pos + 1) == '\n') {
            pos++;
        }
        pos++;
        line++;
        lineStart = pos;
    }

    private void skipWhitespace() {
        while (pos < text.length() && (text.charAt(pos) == ' ' || text.charAt(pos) == '\t' || text.charAt(pos) == '\f')) {
            pos++;
        }
    }

    private static boolean isLineBreak(char c) {
        return c == '\n' || c == '\r';
    }
}
