package glint.scene;

import glint.input.InputException;
import glint.math.Vector3d;
import java.util.Map;
import org.snakeyaml.engine.v2.nodes.Node;

/**
 * One object's or light's mapping in a scene file, its keys already checked: what a type's reader
 * ({@link ShapeType}, {@link LightType}) reads its values from. Each value is checked as it is read,
 * and a bad one is reported at its line and column.
 */
public final class Fields {

    private final YamlTree yaml;
    private final Node node;
    private final Map<String, Node> entries;
    private final String what;

    Fields(YamlTree yaml, Node node, Map<String, Node> entries, String what) {
        this.yaml = yaml;
        this.node = node;
        this.entries = entries;
        this.what = what;
    }

    /** A vector the mapping must have, such as a centre or a position. */
    public Vector3d vector(String key) throws InputException {
        return yaml.vector(required(key), key);
    }

    /** A unit direction the mapping must have: any vector but zero, normalised. */
    public Vector3d direction(String key) throws InputException {
        Node value = required(key);
        Vector3d v = SceneLoader.lengthSafe(yaml.vector(value, key));
        if (v.length() == 0) {
            throw yaml.error(value, key + " must not be the zero vector");
        }
        return v.normalize();
    }

    /**
     * A length the mapping must have, such as a radius: above 0, between 1e-150 and 1e150, so its
     * square is a normal double and intersections neither underflow nor overflow.
     */
    public double length(String key) throws InputException {
        Node value = required(key);
        double length = yaml.number(value, key);
        if (!(length > 0)) {
            throw yaml.error(value, key + " must be > 0, got " + YamlTree.source(value, length));
        }
        if (!(length >= SceneLoader.SHORTEST && length <= SceneLoader.LONGEST)) {
            throw yaml.error(value, key + " must lie between 1e-150 and 1e150 (its square must be a"
                    + " normal double), got " + YamlTree.source(value, length));
        }
        return length;
    }

    /** A number the mapping must have. */
    public double number(String key) throws InputException {
        return yaml.number(required(key), key);
    }

    /** An error about the value of {@code key} (which the mapping has), at its line and column. */
    public InputException error(String key, String problem) {
        Node value = entries.get(key);
        return yaml.error(value != null ? value : node, problem);
    }

    private Node required(String key) throws InputException {
        return yaml.required(node, entries, key, what);
    }
}
