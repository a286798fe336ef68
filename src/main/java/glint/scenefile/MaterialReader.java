package glint.scenefile;

import glint.input.InputException;
import glint.input.Suggestions;
import glint.math.Vector3d;
import glint.registry.MaterialType;
import glint.registry.Registry;
import glint.scene.Material;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.snakeyaml.engine.v2.nodes.MappingNode;
import org.snakeyaml.engine.v2.nodes.Node;
import org.snakeyaml.engine.v2.nodes.ScalarNode;

/**
 * The materials of a scene file: its named {@code materials:} and each object's {@code material:},
 * a name or a mapping of the keys its type reads ({@link MaterialType#keys}), every value checked
 * against its range.
 */
final class MaterialReader {

    /**
     * The largest colour component and kd, ks and kt: shares of the light a surface sends back (1 is
     * all of it), allowed above 1 up to the bound of every colour and light of a scene.
     */
    static final double MAX_SHARE = SceneLoader.MAX_RADIANCE;
    /**
     * The largest phong highlight exponent: (r.v)^shininess stays within rounding of 1 where r.v is
     * a rounding above 1 (at 1e20, 1 + 1e-16 would give infinity).
     */
    static final double MAX_SHININESS = 1e6;
    /** The range of ior: far wider than that of real media (about 1 to 4) and their ratios. */
    static final double MIN_IOR = 0.1, MAX_IOR = 100;

    private final YamlTree yaml;
    private final Map<String, MaterialType> types = new LinkedHashMap<>();
    private final Map<String, Material> named = new LinkedHashMap<>(); // presets first, for hints
    /** {@code type} and every key some type reads: a key beyond them is unknown, with a hint among them. */
    private final Set<String> anyTypesKeys = new LinkedHashSet<>(List.of("type"));
    private final Material defaultMaterial;

    MaterialReader(YamlTree yaml, Registry registry) {
        this.yaml = yaml;
        for (MaterialType type : registry.materials()) {
            types.put(type.name(), type);
            named.put(type.name(), type.preset());
        }
        for (String key : concat(MaterialType.COMMON_KEYS, MaterialType.PHYSICAL_KEYS)) {
            if (types.values().stream().anyMatch(type -> type.keys().contains(key))) {
                anyTypesKeys.add(key);
            }
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

    private Material materialMap(Node node, String what) throws InputException {
        Map<String, Node> m = yaml.mapping(node, what, anyTypesKeys);
        Node typeNode = m.get("type");
        if (typeNode == null) {
            throw yaml.error(node, "missing required key 'type' in " + what
                    + " (one of: " + String.join(", ", types.keySet()) + ")");
        }
        String typeName = yaml.string(typeNode, "material type");
        MaterialType type = types.get(typeName);
        if (type == null) {
            throw yaml.error(typeNode, "unknown material type " + InputException.quote(typeName)
                    + Suggestions.hint(typeName, types.keySet()));
        }
        checkKeysOf(type, (MappingNode) node);
        Material p = type.preset();
        Vector3d color = m.containsKey("color") ? color(m.get("color")) : p.color();
        double kd = share(m, "kd", p.kd());
        double ks = share(m, "ks", p.ks());
        double kt = share(m, "kt", p.kt());
        double shininess = shininess(m, p.shininess());
        double ior = m.containsKey("ior") ? ior(m.get("ior")) : p.ior();
        double roughness = p.roughness();
        if (m.containsKey("roughness")) {
            roughness = yaml.number(m.get("roughness"), "roughness");
            if (roughness < 0 || roughness > 1) {
                throw yaml.error(m.get("roughness"), "roughness must lie in [0, 1], got "
                        + YamlTree.source(m.get("roughness"), roughness));
            }
        }
        return new Material(p.type(), color, kd, ks, kt, shininess, ior, roughness);
    }

    /** Refuses, at the key, a key some other type reads but {@code type} does not. */
    private void checkKeysOf(MaterialType type, MappingNode map) throws InputException {
        for (var tuple : map.getValue()) {
            String key = ((ScalarNode) tuple.getKeyNode()).getValue();
            if (!key.equals("type") && !type.keys().contains(key)) {
                List<String> readers = types.values().stream().filter(other -> other.keys().contains(key))
                        .map(MaterialType::name).toList();
                throw yaml.error(tuple.getKeyNode(), (startsWithVowel(type.name()) ? "an " : "a ") + type.name()
                        + " material has no " + key + " (" + key + " is a key of " + listed(readers) + ")");
            }
        }
    }

    private static boolean startsWithVowel(String word) {
        return !word.isEmpty() && "aeiou".indexOf(Character.toLowerCase(word.charAt(0))) >= 0;
    }

    /** "a", "a and b", "a, b and c". */
    private static String listed(List<String> names) {
        int last = names.size() - 1;
        return last == 0 ? names.get(0) : String.join(", ", names.subList(0, last)) + " and " + names.get(last);
    }

    private static List<String> concat(List<String> a, List<String> b) {
        List<String> both = new ArrayList<>(a);
        both.addAll(b);
        return both;
    }

    private Vector3d color(Node node) throws InputException {
        Vector3d c = yaml.color(node, "color");
        if (c.maxComponent() > MAX_SHARE) {
            throw yaml.error(node, "color must be at most 1e30 in each component, got "
                    + InputException.beyond(c.maxComponent(), MAX_SHARE, 3) + " (a material's color is the share of "
                    + "the light it sends back, 1 for all of it)");
        }
        return c;
    }

    /** kd, ks or kt: from 0 to {@link #MAX_SHARE}. */
    private double share(Map<String, Node> m, String key, double fallback) throws InputException {
        double value = atLeastZero(m, key, fallback);
        if (value > MAX_SHARE) {
            throw yaml.error(m.get(key), key + " must be at most 1e30, got " + YamlTree.source(m.get(key), value)
                    + " (the share of the light it sends back, 1 for all of it)");
        }
        return value;
    }

    private double shininess(Map<String, Node> m, double fallback) throws InputException {
        double value = atLeastZero(m, "shininess", fallback);
        if (value > MAX_SHININESS) {
            throw yaml.error(m.get("shininess"), "shininess must be at most 1e6, got "
                    + YamlTree.source(m.get("shininess"), value) + " (the highlight's exponent: 10 is broad, 1000 a point)");
        }
        return value;
    }

    private double ior(Node node) throws InputException {
        double ior = yaml.number(node, "ior");
        if (!(ior > 0)) {
            throw yaml.error(node, "ior must be > 0, got " + YamlTree.source(node, ior));
        }
        if (ior < MIN_IOR || ior > MAX_IOR) {
            throw yaml.error(node, "ior must lie between 0.1 and 100 (water is 1.33, glass 1.5, diamond 2.4), got "
                    + YamlTree.source(node, ior));
        }
        return ior;
    }

    private double atLeastZero(Map<String, Node> m, String key, double fallback) throws InputException {
        if (!m.containsKey(key)) {
            return fallback;
        }
        double value = yaml.number(m.get(key), key);
        if (value < 0) {
            throw yaml.error(m.get(key), key + " must be >= 0, got " + YamlTree.source(m.get(key), value));
        }
        return value;
    }
}
