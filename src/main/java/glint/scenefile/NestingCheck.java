package glint.scenefile;

import glint.input.InputException;
import java.util.ArrayDeque;
import java.util.Deque;

/**
 * Refuses YAML nested deeper than a scene can be before a parser recurses into it: counts block
 * levels (indentation and "- " items) and flow levels ([ and {, outside quotes and comments).
 */
final class NestingCheck {

    private NestingCheck() {
    }

    static void check(String file, String text, int maxDepth) throws InputException {
        Deque<Integer> indents = new ArrayDeque<>();
        int flowDepth = 0;
        int lineNumber = 0;
        for (String line : text.split("\n", -1)) {
            lineNumber++;
            int indent = 0;
            while (indent < line.length() && line.charAt(indent) == ' ') {
                indent++;
            }
            if (indent == line.length() || line.charAt(indent) == '#') {
                continue;
            }
            int column = indent;
            if (flowDepth == 0) {
                while (!indents.isEmpty() && indents.peek() >= indent) {
                    indents.pop();
                }
                indents.push(indent);
                // "- - x" opens a sequence level per dash
                while (column + 1 < line.length() && line.charAt(column) == '-' && line.charAt(column + 1) == ' ') {
                    indents.push(column + 2);
                    column += 2;
                    while (column < line.length() && line.charAt(column) == ' ') {
                        column++;
                    }
                }
                if (indents.size() > maxDepth) {
                    throw tooDeep(file, lineNumber, column + 1, maxDepth);
                }
            }
            flowDepth = scanFlow(file, line, lineNumber, column, flowDepth, indents.size(), maxDepth);
        }
    }

    /** Follows [ { ] } through one line; returns the flow depth at its end. */
    private static int scanFlow(String file, String line, int lineNumber, int from, int depth, int blockDepth,
                                int maxDepth) throws InputException {
        char quote = 0;
        for (int i = from; i < line.length(); i++) {
            char c = line.charAt(i);
            if (quote != 0) {
                if (c == quote) {
                    quote = 0;
                }
                continue;
            }
            if ((c == '\'' || c == '"') && opensScalar(line, from, i)) {
                quote = c;
            } else if (c == '#' && (i == 0 || line.charAt(i - 1) == ' ')) {
                break;
            } else if (c == '[' || c == '{') {
                depth++;
                if (depth + blockDepth > maxDepth) {
                    throw tooDeep(file, lineNumber, i + 1, maxDepth);
                }
            } else if ((c == ']' || c == '}') && depth > 0) {
                depth--;
            }
        }
        return depth;
    }

    /**
     * True when a quote at {@code i} starts a quoted scalar: first on the line, or after one of
     * {@code [ { , : - ?} and spaces. An apostrophe inside a plain word ({@code it's}) quotes nothing,
     * so the brackets after it still count.
     */
    private static boolean opensScalar(String line, int from, int i) {
        int j = i - 1;
        while (j >= from && (line.charAt(j) == ' ' || line.charAt(j) == '\t')) {
            j--;
        }
        return j < from || "[{,:-?".indexOf(line.charAt(j)) >= 0;
    }

    private static InputException tooDeep(String file, int line, int column, int maxDepth) {
        return new InputException(file, line, column,
                "nested more than " + maxDepth + " levels deep (a scene needs at most 4)");
    }
}
