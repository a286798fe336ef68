package glint.scenefile;

import glint.input.InputException;
import glint.input.Suggestions;
import glint.registry.MaterialType;
import glint.registry.Registry;
import glint.scene.Material;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.snakeyaml.engine.v2.nodes.MappingNode;
import org.snakeyaml.engine.v2.nodes.Node;
import org.snakeyaml.engine.v2.nodes.ScalarNode;

/**
 * The materials of a scene file: its named {@code materials:} and each object's {@code material:},
 * a name or a mapping. Of a mapping it finds the type, checks its keys against the keys that type
 * reads ({@link MaterialType#keys}) and hands it to the type, which reads and checks the values.
 */
final class MaterialReader {

    private final YamlTree yaml;
    private final Map<String, MaterialType> types = new LinkedHashMap<>();
    private final Map<String, Material> named = new LinkedHashMap<>(); // presets first, for hints
    private final Material defaultMaterial;

    MaterialReader(YamlTree yaml, Registry registry) {
        this.yaml = yaml;
        for (MaterialType type : registry.materials()) {
            types.put(type.name(), type);
            named.put(type.name(), type.preset());
        }
        defaultMaterial = registry.defaultMaterial().preset();
    }

    /** {@code materials:}, a mapping of names to materials. */
    void namedMaterials(Node node) throws InputException {
        if (YamlTree.isNull(node)) {
            return;
        }
        if (!(node instanceof MappingNode map)) {
            throw yaml.error(node, "expected a mapping of material names to materials, got " + YamlTree.describe(node));
        }
        Set<String> seen = new LinkedHashSet<>();
        for (var tuple : map.getValue()) {
            if (YamlTree.isMergeKey(tuple.getKeyNode())) { // not a material named <<
                throw yaml.mergeKeyError(tuple.getKeyNode(), "materials");
            }
            String name = yaml.string(tuple.getKeyNode(), "a material name");
            if (types.containsKey(name)) {
                throw yaml.error(tuple.getKeyNode(), "material name " + InputException.quote(name)
                        + " is a preset and cannot be redefined (choose another name)");
            }
            if (!seen.add(name)) {
                throw yaml.error(tuple.getKeyNode(), "duplicate material name " + InputException.quote(name));
            }
            named.put(name, materialMap(tuple.getValueNode(), "material " + InputException.quote(name)));
        }
    }

    /** An object's {@code material:} (a name or a mapping), or the registry's default preset when it has none. */
    Material of(Map<String, Node> object) throws InputException {
        return object.containsKey("material") ? material(object.get("material")) : defaultMaterial;
    }

    private Material material(Node node) throws InputException {
        if (node instanceof ScalarNode && !YamlTree.isNull(node)) {
            String name = yaml.string(node, "material");
            Material found = named.get(name);
            if (found == null) {
                throw yaml.error(node, "unknown material " + InputException.quote(name) + Suggestions.hint(name, named.keySet()));
            }
            return found;
        }
        return materialMap(node, "material");
    }

    /** A material mapping: its type, then its keys checked against the type's, read by the type. */
    private Material materialMap(Node node, String what) throws InputException {
        MaterialType type = typeOf(node, what);
        Set<String> keys = new LinkedHashSet<>(List.of("type"));
        keys.addAll(type.keys());
        Map<String, Node> m = yaml.mapping(node, what, keys, key -> keyOfAnotherType(type, key));
        return type.read(new YamlFields(yaml, node, m, what));
    }

    /** The type a material mapping names, wherever its {@code type} key stands. */
    private MaterialType typeOf(Node node, String what) throws InputException {
        if (!(node instanceof MappingNode map)) {
            throw yaml.error(node, "expected a mapping for " + what + ", got " + YamlTree.describe(node));
        }
        Node mergeKey = null;
        for (var tuple : map.getValue()) {
            if (tuple.getKeyNode() instanceof ScalarNode key && key.getValue().equals("type")) {
                String name = yaml.string(tuple.getValueNode(), "material type");
                MaterialType type = types.get(name);
                if (type == null) {
                    throw yaml.error(tuple.getValueNode(), "unknown material type " + InputException.quote(name)
                            + Suggestions.hint(name, types.keySet()));
                }
                return type;
            }
            if (mergeKey == null && YamlTree.isMergeKey(tuple.getKeyNode())) {
                mergeKey = tuple.getKeyNode();
            }
        }
        if (mergeKey != null) { // its type may be among the keys it would merge
            throw yaml.mergeKeyError(mergeKey, what);
        }
        throw yaml.error(node, "missing required key 'type' in " + what
                + " (one of: " + String.join(", ", types.keySet()) + ")");
    }

    /**
     * The problem with {@code key} in a material of {@code type}, which does not read it, when other
     * types do: which ones, and the fix. Null when no type reads it: the key is unknown.
     */
    private String keyOfAnotherType(MaterialType type, String key) {
        List<String> readers = types.values().stream().filter(other -> other.keys().contains(key))
                .map(MaterialType::name).toList();
        if (readers.isEmpty()) {
            return null;
        }
        String retyped = readers.stream().map(name -> "type: " + name).collect(Collectors.joining(" or "));
        return (startsWithVowel(type.name()) ? "an " : "a ") + type.name() + " material has no " + key + " ("
                + key + " is a key of " + listed(readers) + "; write " + retyped + ", or remove " + key + ")";
    }

    private static boolean startsWithVowel(String word) {
        return !word.isEmpty() && "aeiou".indexOf(Character.toLowerCase(word.charAt(0))) >= 0;
    }

    /** "a", "a and b", "a, b and c". */
    private static String listed(List<String> names) {
        int last = names.size() - 1;
        return last == 0 ? names.get(0) : String.join(", ", names.subList(0, last)) + " and " + names.get(last);
    }
}
