package glint.scenefile;

import glint.input.InputException;
import glint.input.Suggestions;
import glint.input.TextFiles;
import glint.math.Vector3d;
import glint.registry.LightType;
import glint.registry.Registry;
import glint.registry.ShapeType;
import glint.scene.Camera;
import glint.scene.Light;
import glint.scene.RenderBlock;
import glint.scene.Scene;
import glint.scene.SceneObject;
import glint.scene.Shape;
import glint.scene.View;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.snakeyaml.engine.v2.api.LoadSettings;
import org.snakeyaml.engine.v2.composer.Composer;
import org.snakeyaml.engine.v2.parser.Parser;
import org.snakeyaml.engine.v2.parser.ParserImpl;
import org.snakeyaml.engine.v2.scanner.StreamReader;
import org.snakeyaml.engine.v2.exceptions.Mark;
import org.snakeyaml.engine.v2.exceptions.MarkedYamlEngineException;
import org.snakeyaml.engine.v2.exceptions.YamlEngineException;
import org.snakeyaml.engine.v2.nodes.MappingNode;
import org.snakeyaml.engine.v2.nodes.Node;
import org.snakeyaml.engine.v2.nodes.ScalarNode;

/** Reads a scene file (docs/scene-format.md) into an immutable {@link Scene}, or explains what is wrong. */
public final class SceneLoader {

    private static final Set<String> TOP_KEYS =
            ordered("camera", "background", "ambient", "lights", "materials", "objects", "views", "render");
    /** Keys 1 to 9 of the window go to the views. */
    public static final int MAX_VIEWS = 9;

    /**
     * The shortest and longest lengths a scene may give a radius or the camera's view: their squares
     * stay normal doubles, so intersections and normals neither underflow to 0 nor overflow.
     */
    static final double SHORTEST = 1e-150, LONGEST = 1e150;

    private final String file;
    private final YamlTree yaml;
    private final CameraReader cameras;
    private final SceneLimits limits;
    private final Map<String, ShapeType<?>> shapeTypes = new LinkedHashMap<>();
    private final Map<String, LightType<?>> lightTypes = new LinkedHashMap<>();
    private final MaterialReader materials;

    private SceneLoader(String file, SceneLimits limits, Registry registry) {
        this.file = file;
        this.yaml = new YamlTree(file);
        this.cameras = new CameraReader(yaml);
        this.limits = limits;
        registry.shapes().forEach(type -> shapeTypes.put(type.name(), type));
        registry.lights().forEach(type -> lightTypes.put(type.name(), type));
        this.materials = new MaterialReader(yaml, registry);
    }

    /** Loads a scene file; {@code path} is also how the file is named in error messages. */
    public static Scene load(Path path) throws InputException {
        return load(path, SceneLimits.DEFAULT);
    }

    /** Loads a scene file within the given limits. */
    public static Scene load(Path path, SceneLimits limits) throws InputException {
        return parse(path.toString(), read(path, limits), limits);
    }

    /** Parses scene text; {@code file} names it in error messages. */
    public static Scene parse(String file, String text) throws InputException {
        return parse(file, text, SceneLimits.DEFAULT);
    }

    /** Parses scene text within the given limits. */
    public static Scene parse(String file, String text, SceneLimits limits) throws InputException {
        return parse(file, text, limits, Registry.STANDARD);
    }

    /** Parses scene text within the given limits, knowing the types {@code registry} lists. */
    public static Scene parse(String file, String text, SceneLimits limits, Registry registry)
            throws InputException {
        if (text.length() > limits.maxFileBytes()) {
            throw tooBig(file, text.length(), limits);
        }
        InputException longLine = TextFiles.lineTooLong(file, text, SceneLimits.MAX_LINE_CHARS);
        if (longLine != null) {
            throw longLine;
        }
        NestingCheck.check(file, text, SceneLimits.MAX_NESTING);
        return new SceneLoader(file, limits, registry).scene(compose(file, text, limits));
    }

    private static InputException tooBig(String file, long size, SceneLimits limits) {
        return new InputException(file, 0, 0, tooBigProblem(size, limits));
    }

    private static String tooBigProblem(long size, SceneLimits limits) {
        return TextFiles.fileIsLargerThan(size, limits.maxFileBytes(), "the largest scene accepted")
                + " (config key max_scene_bytes)";
    }

    /** The file's text: a regular file (never a FIFO or device), within the size limit, UTF-8. */
    public static String read(Path path, SceneLimits limits) throws InputException {
        byte[] bytes = TextFiles.readBounded(path, limits.maxFileBytes(), size -> tooBigProblem(size, limits));
        return TextFiles.utf8(path.toString(), bytes);
    }

    /** The most aliases of lists or mappings a scene may have: an alias bomb's copies grow exponentially. */
    static final int MAX_ALIASES = 50;

    private static Node compose(String file, String text, SceneLimits limits) throws InputException {
        LoadSettings settings = LoadSettings.builder()
                .setLabel(file)
                .setAllowDuplicateKeys(true) // reported by YamlTree with a position
                .setMaxAliasesForCollections(MAX_ALIASES)
                .setAllowRecursiveKeys(false)
                .setCodePointLimit((int) Math.min(Integer.MAX_VALUE, limits.maxFileBytes()))
                .setUseMarks(true)
                .build();
        Optional<Node> root;
        try {
            Parser parser = new TagRefusingParser(new AliasCountingParser(
                    new ParserImpl(settings, new StreamReader(settings, text)), MAX_ALIASES));
            root = new Composer(settings, parser).getSingleNode();
        } catch (AliasCountingParser.TooManyAliases e) {
            throw new InputException(file, e.line, e.column, TOO_MANY_ALIASES);
        } catch (TagRefusingParser.TagFound e) {
            throw new InputException(file, e.line, e.column, "YAML tags such as " + InputException.quote(e.tag)
                    + " are not supported (write the value without it; a number is written plainly, a name too)");
        } catch (MarkedYamlEngineException e) {
            InputException unclosed = unclosed(file, e);
            if (unclosed != null) {
                throw unclosed;
            }
            Mark mark = e.getProblemMark().or(e::getContextMark).orElse(null);
            String what = e.getProblem() != null ? e.getProblem() : "malformed YAML";
            String problem = InputException.cutLongWords("YAML syntax error: " + what
                    + (e.getContext() != null && !e.getContext().isEmpty() ? " (" + e.getContext() + ")" : "")
                    + (what.contains("<block end>") ? "; check the indentation" : ""));
            throw mark == null
                    ? new InputException(file, 0, 0, problem)
                    : new InputException(file, mark.getLine() + 1, mark.getColumn() + 1, problem);
        } catch (YamlEngineException e) {
            String message = String.valueOf(e.getMessage());
            throw new InputException(file, 0, 0, message.startsWith("Number of aliases") ? TOO_MANY_ALIASES
                    : "YAML error: " + InputException.cutLongWords(message));
        } catch (StackOverflowError e) {
            throw new InputException(file, 0, 0, "the YAML is nested too deeply to read");
        }
        if (root.isEmpty() || YamlTree.isNull(root.get())) {
            throw new InputException(file, 1, 1,
                    "the scene is empty (expected a mapping with keys such as camera, lights, objects)");
        }
        return root.get();
    }

    /**
     * A list ({@code [}) or mapping ({@code {}) written on one line and never closed: the parser notices only
     * where something else comes, often a line or more later ({@code expected ',' or ']', but got :}). Reported
     * where it was opened, in words: what is missing and where the parser found the list still open. Null for
     * any other syntax error.
     */
    static InputException unclosed(String file, MarkedYamlEngineException e) {
        String problem = String.valueOf(e.getProblem());
        String context = String.valueOf(e.getContext());
        boolean list = context.contains("flow sequence") && problem.startsWith("expected ',' or ']'");
        boolean mapping = context.contains("flow mapping") && problem.startsWith("expected ',' or '}'");
        if (!(list || mapping) || e.getContextMark().isEmpty() || e.getProblemMark().isEmpty()) {
            return null;
        }
        Mark open = e.getContextMark().get(), found = e.getProblemMark().get();
        String got = problem.contains("but got ") ? problem.substring(problem.indexOf("but got ") + 8).strip() : "";
        String what = got.isEmpty() || got.startsWith("<stream end>") ? "the file ended"
                : got.startsWith("<") ? "other text came" : InputException.quote(got) + " came";
        String message = (list ? "this list, opened with '[', is not closed: add the ']' that ends it"
                : "this mapping, opened with '{', is not closed: add the '}' that ends it")
                + " (at line " + (found.getLine() + 1) + ", column " + (found.getColumn() + 1) + " it was still open and "
                + what + " instead of ',' or '" + (list ? "]" : "}") + "')";
        return new InputException(file, open.getLine() + 1, open.getColumn() + 1, InputException.cutLongWords(message));
    }

    private static final String TOO_MANY_ALIASES = "YAML error: more than " + MAX_ALIASES
            + " aliases of lists or mappings (an alias bomb?); write the values out";

    private Scene scene(Node root) throws InputException {
        Map<String, Node> top = yaml.mapping(root, "the scene", TOP_KEYS);
        if (top.containsKey("materials")) {
            materials.namedMaterials(top.get("materials"));
        }
        // "camera:" with nothing after it, like "camera: {}", keeps every default
        Camera camera = top.containsKey("camera") && !YamlTree.isNull(top.get("camera"))
                ? cameras.camera(top.get("camera")) : Camera.defaults();
        Vector3d background = top.containsKey("background")
                ? radiance(top.get("background"), "background") : Vector3d.ZERO;
        Vector3d ambient = top.containsKey("ambient") ? radiance(top.get("ambient"), "ambient") : Vector3d.ZERO;
        List<Light> lights = new ArrayList<>();
        if (top.containsKey("lights")) {
            for (Node item : yaml.sequence(top.get("lights"), "lights")) {
                if (lights.size() == limits.maxLights()) {
                    throw yaml.error(item, "too many lights: more than " + limits.maxLights()
                            + " (config key max_lights)");
                }
                lights.add(light(item));
            }
        }
        List<SceneObject> objects = new ArrayList<>();
        if (top.containsKey("objects")) {
            for (Node item : yaml.sequence(top.get("objects"), "objects")) {
                if (objects.size() == limits.maxObjects()) {
                    throw yaml.error(item, "too many objects: more than " + limits.maxObjects()
                            + " (config key max_objects)");
                }
                objects.add(object(item));
            }
        }
        List<View> views = top.containsKey("views") ? cameras.views(top.get("views")) : List.of();
        RenderBlock render = top.containsKey("render")
                ? new RenderBlockReader(yaml, file).read(top.get("render")) : RenderBlock.NONE;
        return new Scene(camera, background, ambient, lights, objects, views, render);
    }

    private SceneObject object(Node node) throws InputException {
        ShapeType<?> type = shapeTypes.get(kind(node, "object", shapeTypes.keySet()));
        Set<String> keys = ordered("type");
        keys.addAll(type.keys());
        keys.add("material");
        Map<String, Node> m = yaml.mapping(node, type.name(), keys);
        Shape shape = type.reader().read(new YamlFields(yaml, node, m, type.name()));
        return new SceneObject(shape, materials.of(m));
    }

    private Light light(Node node) throws InputException {
        LightType<?> type = lightTypes.get(kind(node, "light", lightTypes.keySet()));
        String what = type.name() + " light";
        Set<String> keys = ordered("type");
        keys.addAll(type.keys());
        keys.add("color");
        keys.add("intensity");
        Map<String, Node> m = yaml.mapping(node, what, keys);
        Vector3d color = m.containsKey("color") ? yaml.color(m.get("color"), "color") : Vector3d.ONE;
        double intensity = 1;
        if (m.containsKey("intensity")) {
            intensity = yaml.number(m.get("intensity"), "intensity");
            if (intensity < 0) {
                throw yaml.error(m.get("intensity"), "intensity must be >= 0, got "
                        + YamlTree.source(m.get("intensity"), intensity));
            }
        }
        double brightest = color.maxComponent() * intensity;
        if (brightest > MAX_RADIANCE) {
            throw yaml.error(m.containsKey("intensity") ? m.get("intensity") : m.get("color"),
                    "color x intensity must be at most 1e30, got " + InputException.beyond(brightest, MAX_RADIANCE, 3)
                    + " (the image stores radiance as float, up to 3.4e38)");
        }
        return type.reader().read(new YamlFields(yaml, node, m, what), color, intensity);
    }

    /** The {@code type} of an object or light mapping, checked against the known types. */
    private String kind(Node node, String what, Set<String> types) throws InputException {
        if (!(node instanceof MappingNode map)) {
            throw yaml.error(node, "expected a mapping for " + what + ", got " + YamlTree.describe(node));
        }
        Node mergeKey = null;
        for (var tuple : map.getValue()) {
            if (tuple.getKeyNode() instanceof ScalarNode k && k.getValue().equals("type")) {
                String type = yaml.string(tuple.getValueNode(), what + " type");
                if (!types.contains(type)) {
                    throw yaml.error(tuple.getValueNode(), "unknown " + what + " type " + InputException.quote(type)
                            + Suggestions.hint(type, types));
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
        throw yaml.error(node, "missing required key 'type' in " + what + " (one of: " + String.join(", ", types) + ")");
    }

    /** The brightest a light (color x intensity), a background or an ambient colour may be. */
    static final double MAX_RADIANCE = 1e30;

    /** A background or ambient colour: a colour of at most {@link #MAX_RADIANCE}. */
    private Vector3d radiance(Node node, String what) throws InputException {
        Vector3d c = yaml.color(node, what);
        if (c.maxComponent() > MAX_RADIANCE) {
            throw yaml.error(node, what + " must be at most 1e30 in each component, got "
                    + InputException.beyond(c.maxComponent(), MAX_RADIANCE, 3)
                    + " (the image stores radiance as float, up to 3.4e38)");
        }
        return c;
    }

    /**
     * The vector itself when its length is a normal double (so valid scenes keep their exact values),
     * otherwise divided by its largest component first: a direction such as [1e200, -1e200, 0] or
     * [1e-200, 0, 0] then normalises instead of overflowing to infinity or underflowing to zero.
     */
    static Vector3d lengthSafe(Vector3d v) {
        double length = v.length();
        if (Double.isFinite(length) && length > SHORTEST) {
            return v;
        }
        double largest = Math.max(Math.abs(v.x()), Math.max(Math.abs(v.y()), Math.abs(v.z())));
        return largest == 0 ? v : new Vector3d(v.x() / largest, v.y() / largest, v.z() / largest);
    }

    private static Set<String> ordered(String... keys) {
        return new LinkedHashSet<>(List.of(keys));
    }
}
