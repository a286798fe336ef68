package glint.scenefile;

import glint.input.InputException;
import glint.input.Suggestions;
import glint.math.Vector3d;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import java.util.regex.Pattern;
import org.snakeyaml.engine.v2.exceptions.Mark;
import org.snakeyaml.engine.v2.nodes.MappingNode;
import org.snakeyaml.engine.v2.nodes.Node;
import org.snakeyaml.engine.v2.nodes.NodeTuple;
import org.snakeyaml.engine.v2.nodes.ScalarNode;
import org.snakeyaml.engine.v2.nodes.SequenceNode;

/** Typed, position-aware reads from a composed YAML node tree; every failure names file:line:col. */
final class YamlTree {

    private static final Pattern NUMBER =
            Pattern.compile("[-+]?(\\.[0-9]+|[0-9]+(\\.[0-9]*)?)([eE][-+]?[0-9]+)?");
    private static final Pattern NON_FINITE = Pattern.compile("[-+]?\\.(inf|Inf|INF)|\\.(nan|NaN|NAN)");

    private final String file;

    YamlTree(String file) {
        this.file = file;
    }

    InputException error(Node node, String problem) {
        Mark mark = node.getStartMark().orElse(null);
        return mark == null
                ? new InputException(file, 0, 0, problem)
                : new InputException(file, mark.getLine() + 1, mark.getColumn() + 1, problem);
    }

    static boolean isNull(Node node) {
        return node instanceof ScalarNode s && s.isPlain()
                && (s.getValue().isEmpty() || s.getValue().equals("~") || s.getValue().equals("null"));
    }

    /**
     * The entries of a mapping, keyed by name, after checking that every key is one of
     * {@code allowed} and none repeats. {@code what} names the mapping in messages ("sphere").
     */
    Map<String, Node> mapping(Node node, String what, Set<String> allowed) throws InputException {
        return mapping(node, what, allowed, key -> null);
    }

    /**
     * The entries of a mapping as {@link #mapping(Node, String, Set)} reads them, where a key not
     * {@code allowed} is refused with the problem {@code refusal} gives for it, or when that is null
     * is unknown, with a hint among {@code allowed}.
     */
    Map<String, Node> mapping(Node node, String what, Set<String> allowed, Function<String, String> refusal)
            throws InputException {
        if (!(node instanceof MappingNode map)) {
            throw error(node, "expected a mapping for " + what + ", got " + describe(node));
        }
        Map<String, Node> entries = new LinkedHashMap<>();
        for (NodeTuple tuple : map.getValue()) {
            Node keyNode = tuple.getKeyNode();
            if (!(keyNode instanceof ScalarNode keyScalar)) {
                throw error(keyNode, "expected a plain key in " + what + ", got " + describe(keyNode));
            }
            String key = keyScalar.getValue();
            if (isMergeKey(keyScalar)) {
                throw mergeKeyError(keyNode, what);
            }
            if (!allowed.contains(key)) {
                String refused = refusal.apply(key);
                throw error(keyNode, refused != null ? refused : "unknown key " + InputException.quote(key) + " in "
                        + what + Suggestions.hint(key, allowed));
            }
            if (entries.putIfAbsent(key, tuple.getValueNode()) != null) {
                throw error(keyNode, "duplicate key " + InputException.quote(key) + " in " + what);
            }
        }
        return entries;
    }

    /** Whether a key is YAML's merge key, {@code <<} written plainly. */
    static boolean isMergeKey(Node key) {
        return key instanceof ScalarNode s && s.isPlain() && s.getValue().equals("<<");
    }

    /** The error for a merge key in the mapping {@code what}, at the key. */
    InputException mergeKeyError(Node key, String what) {
        return error(key, "merge keys (<<) are not supported in " + what
                + "; write the keys out (an alias of a whole mapping, such as *name, works)");
    }

    /** The mapping's value for a key it must have. */
    Node required(Node mapNode, Map<String, Node> entries, String key, String what) throws InputException {
        Node value = entries.get(key);
        if (value == null) {
            throw error(mapNode, "missing required key '" + key + "' in " + what);
        }
        return value;
    }

    /** The items of a sequence; a null value (key with nothing after it) is an empty list. */
    List<Node> sequence(Node node, String what) throws InputException {
        if (isNull(node)) {
            return List.of();
        }
        if (!(node instanceof SequenceNode seq)) {
            throw error(node, "expected a list of " + what + ", got " + describe(node));
        }
        return seq.getValue();
    }

    String string(Node node, String what) throws InputException {
        if (!(node instanceof ScalarNode s) || isNull(node)) {
            throw error(node, "expected a name for " + what + ", got " + describe(node));
        }
        return s.getValue();
    }

    double number(Node node, String what) throws InputException {
        if (!(node instanceof ScalarNode s) || isNull(node)) {
            throw error(node, "expected a number for " + what + ", got " + describe(node));
        }
        String text = s.getValue().trim();
        if (!s.isPlain()) {
            throw error(node, "expected a number for " + what + ", got the quoted string " + InputException.quote(text));
        }
        if (NON_FINITE.matcher(text).matches()) {
            throw error(node, "expected a finite number for " + what + ", got " + InputException.quote(text));
        }
        if (!NUMBER.matcher(text).matches()) {
            throw error(node, "expected a number for " + what + ", got " + InputException.quote(text));
        }
        double value = Double.parseDouble(text);
        if (!Double.isFinite(value)) {
            throw error(node, "expected a finite number for " + what + ", got " + InputException.quote(text) + " (too large)");
        }
        return value;
    }

    Vector3d vector(Node node, String what) throws InputException {
        if (!(node instanceof SequenceNode seq)) {
            throw error(node, "expected a list of 3 numbers for " + what + " like [0, 1, 0], got "
                    + describe(node));
        }
        List<Node> items = seq.getValue();
        if (items.size() != 3) {
            throw error(node, "expected a list of 3 numbers for " + what + ", got " + items.size()
                    + (items.size() == 1 ? " element" : " elements"));
        }
        return new Vector3d(number(items.get(0), what), number(items.get(1), what), number(items.get(2), what));
    }

    /** A colour: three finite numbers, none negative. */
    Vector3d color(Node node, String what) throws InputException {
        Vector3d c = vector(node, what);
        if (c.x() < 0 || c.y() < 0 || c.z() < 0) {
            throw error(node, what + " must not have negative components, got " + c);
        }
        return c;
    }

    /**
     * A number as the user wrote it (for range messages), e.g. "0" rather than "0.0", cut after 60
     * characters as every value a message echoes.
     */
    static String source(Node node, double value) {
        return node instanceof ScalarNode s ? InputException.cut(s.getValue().trim()) : String.valueOf(value);
    }

    static String describe(Node node) {
        if (isNull(node)) {
            return "nothing";
        }
        if (node instanceof ScalarNode s) {
            return InputException.quote(s.getValue());
        }
        return node instanceof SequenceNode ? "a list" : "a mapping";
    }

}
