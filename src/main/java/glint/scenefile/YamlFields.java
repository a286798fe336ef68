package glint.scenefile;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.registry.Fields;
import java.util.Map;
import org.snakeyaml.engine.v2.nodes.Node;
import org.snakeyaml.engine.v2.nodes.ScalarNode;

/** The {@link Fields} of one mapping of a scene file: each value read from its YAML node. */
final class YamlFields implements Fields {

    private final YamlTree yaml;
    private final Node node;
    private final Map<String, Node> entries;
    private final String what;

    YamlFields(YamlTree yaml, Node node, Map<String, Node> entries, String what) {
        this.yaml = yaml;
        this.node = node;
        this.entries = entries;
        this.what = what;
    }

    @Override
    public Vector3d vector(String key) throws InputException {
        return yaml.vector(required(key), key);
    }

    @Override
    public Vector3d direction(String key) throws InputException {
        Node value = required(key);
        Vector3d v = SceneLoader.lengthSafe(yaml.vector(value, key));
        if (v.length() == 0) {
            throw yaml.error(value, key + " must not be the zero vector");
        }
        return v.normalize();
    }

    @Override
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

    @Override
    public double number(String key) throws InputException {
        return yaml.number(required(key), key);
    }

    @Override
    public Vector3d color(String key) throws InputException {
        return yaml.color(required(key), key);
    }

    @Override
    public boolean has(String key) {
        return entries.containsKey(key);
    }

    @Override
    public String written(String key) {
        Node value = entries.get(key);
        if (value == null) {
            throw new IllegalArgumentException(what + " has no " + key);
        }
        return value instanceof ScalarNode s ? InputException.cut(s.getValue().trim()) : YamlTree.describe(value);
    }

    @Override
    public InputException error(String key, String problem) {
        Node value = entries.get(key);
        return yaml.error(value != null ? value : node, problem);
    }

    private Node required(String key) throws InputException {
        return yaml.required(node, entries, key, what);
    }
}
