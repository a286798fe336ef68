package glint.scenefile;

import glint.input.InputException;
import glint.input.Suggestions;
import glint.scene.RenderBlock;
import glint.render.LightTransport;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.snakeyaml.engine.v2.nodes.Node;

/** Reads a scene's {@code render:} block ({@link RenderBlock}), with the positioned errors of the scene. */
final class RenderBlockReader {

    static final Set<String> KEYS = new LinkedHashSet<>(
            List.of("shading", "integrator", "samples", "noise", "max_samples", "recursion_max", "min_weight", "width", "height", "exposure",
                    "tone"));
    static final List<String> SHADINGS = List.of("cook-torrance", "phong");
    static final List<String> INTEGRATORS = LightTransport.KEYS;
    static final List<String> TONES = List.of("standard", "neutral");
    /** The most stops of exposure either way, as in config.properties. */
    static final double MAX_EXPOSURE = 16;
    /** The largest samples per pixel and image side, as in config.properties. */
    static final int MAX_SAMPLES = 4096, MAX_SIDE = 65536, MAX_RECURSION = 64;
    /** The largest max_samples, as in config.properties. */
    static final int MAX_ADAPTIVE_SAMPLES = 65536;

    private final YamlTree yaml;
    private final String file;

    RenderBlockReader(YamlTree yaml, String file) {
        this.yaml = yaml;
        this.file = file;
    }

    /** The block; "render:" with nothing after it sets nothing. */
    RenderBlock read(Node node) throws InputException {
        if (YamlTree.isNull(node)) {
            return RenderBlock.NONE;
        }
        Map<String, Node> m = yaml.mapping(node, "render", KEYS);
        Map<String, RenderBlock.Place> places = new HashMap<>();
        for (Map.Entry<String, Node> e : m.entrySet()) {
            e.getValue().getStartMark().ifPresent(mark ->
                    places.put(e.getKey(), new RenderBlock.Place(mark.getLine() + 1, mark.getColumn() + 1)));
        }
        String shading = null;
        if (m.containsKey("shading")) {
            shading = yaml.string(m.get("shading"), "shading");
            if (!SHADINGS.contains(shading)) {
                throw yaml.error(m.get("shading"), "unknown shading model " + InputException.quote(shading)
                        + Suggestions.hint(shading, SHADINGS));
            }
        }
        String integrator = null;
        if (m.containsKey("integrator")) {
            integrator = yaml.string(m.get("integrator"), "integrator");
            if (!INTEGRATORS.contains(integrator)) {
                throw yaml.error(m.get("integrator"), "unknown integrator " + InputException.quote(integrator)
                        + ", expected " + LightTransport.IN_WORDS + Suggestions.hint(integrator, INTEGRATORS));
            }
        }
        Integer samples = whole(m, "samples", 1, MAX_SAMPLES);
        if (samples != null && !isPerfectSquare(samples)) {
            throw yaml.error(m.get("samples"), "samples must be a perfect square (1, 4, 9, 16, ...), got " + samples);
        }
        Double noise = null;
        if (m.containsKey("noise")) {
            double threshold = yaml.number(m.get("noise"), "noise");
            if (!(threshold == 0 || (threshold >= 1e-4 && threshold <= 1))) {
                throw yaml.error(m.get("noise"), "noise must be 0 (off) or a number from 0.0001 to 1, got "
                        + YamlTree.source(m.get("noise"), threshold));
            }
            noise = threshold;
        }
        Integer maxSamples = whole(m, "max_samples", 1, MAX_ADAPTIVE_SAMPLES);
        Integer depth = whole(m, "recursion_max", 1, MAX_RECURSION);
        Double minWeight = null;
        if (m.containsKey("min_weight")) {
            double w = yaml.number(m.get("min_weight"), "min_weight");
            if (w < 0 || w > 1) {
                throw yaml.error(m.get("min_weight"), "min_weight must lie in [0, 1], got "
                        + YamlTree.source(m.get("min_weight"), w));
            }
            minWeight = w;
        }
        Double exposure = null;
        if (m.containsKey("exposure")) {
            double stops = yaml.number(m.get("exposure"), "exposure");
            if (!(Math.abs(stops) <= MAX_EXPOSURE)) {
                throw yaml.error(m.get("exposure"), "exposure must be a number of stops from -16 to 16, got "
                        + YamlTree.source(m.get("exposure"), stops));
            }
            exposure = stops;
        }
        String tone = null;
        if (m.containsKey("tone")) {
            tone = yaml.string(m.get("tone"), "tone");
            if (!TONES.contains(tone)) {
                throw yaml.error(m.get("tone"), "unknown tone curve " + InputException.quote(tone)
                        + Suggestions.hint(tone, TONES));
            }
        }
        Integer width = whole(m, "width", 1, MAX_SIDE);
        Integer height = whole(m, "height", 1, MAX_SIDE);
        if ((width == null) != (height == null)) {
            throw yaml.error(node, "the still size needs both width and height in render");
        }
        return new RenderBlock(shading, integrator, samples, depth, minWeight, width, height, exposure, tone, noise,
                maxSamples, file, places);
    }

    private Integer whole(Map<String, Node> m, String key, int min, int max) throws InputException {
        if (!m.containsKey(key)) {
            return null;
        }
        double value = yaml.number(m.get(key), key);
        if (value != Math.rint(value) || value < min || value > max) {
            throw yaml.error(m.get(key), key + " must be a whole number from " + min + " to " + max + ", got "
                    + YamlTree.source(m.get(key), value));
        }
        return (int) value;
    }

    private static boolean isPerfectSquare(int n) {
        int root = (int) Math.round(Math.sqrt(n));
        return root * root == n;
    }
}
