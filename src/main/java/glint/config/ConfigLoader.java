package glint.config;

import glint.image.ViewTransform;
import glint.input.InputException;
import glint.input.Suggestions;
import glint.input.TextFiles;
import glint.render.LightTransport;
import glint.render.Shading;
import java.nio.file.Path;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;

/** Reads config.properties; every key is optional, and a bad one is reported with its line. */
public final class ConfigLoader {

    static final Set<String> KEYS = new LinkedHashSet<>(List.of(
            "debug", "epsilon", "display_scale", "screen_divider", "display_height", "recursion_max",
            "display_width", "name", "scene", "threads", "shading", "integrator", "samples", "noise", "max_samples", "min_weight",
            "move_speed", "turn_speed", "target_fps", "free_flight", "exposure", "tone",
            "max_image_pixels", "max_scene_bytes", "max_objects", "max_lights", "max_recursion"));

    /** The largest config file read; a real one is about 1 KB. */
    static final long MAX_CONFIG_BYTES = 1 << 20;

    /** Whole numbers: ASCII digits only (Java's parser would take other scripts' digits too). */
    private static final Pattern WHOLE = Pattern.compile("[-+]?[0-9]{1,19}");
    /** Decimal numbers: ASCII digits, no hex, no NaN or Infinity, no type suffix. */
    private static final Pattern DECIMAL = Pattern.compile("[-+]?(\\.[0-9]+|[0-9]+(\\.[0-9]*)?)([eE][-+]?[0-9]{1,4})?");

    private final String file;
    private final Map<String, PropertiesText.Entry> entries;

    private ConfigLoader(String file, String text) throws InputException {
        this.file = file;
        this.entries = PropertiesText.parse(file, text);
    }

    /** Loads a config file: a regular file of at most 1 MB of UTF-8 text. */
    public static Config load(Path path) throws InputException {
        return parse(path.toString(), read(path));
    }

    private static String read(Path path) throws InputException {
        byte[] bytes = TextFiles.readBounded(path, MAX_CONFIG_BYTES, size -> TextFiles.fileIsLargerThan(size, MAX_CONFIG_BYTES,
                "the largest config file accepted"));
        return TextFiles.utf8(path.toString(), bytes);
    }

    /**
     * Where a key is set in a config file, as an error carrying {@code problem}; the position is
     * unknown (0) when the key is not set.
     */
    public static InputException errorAt(Path path, String key, String problem) throws InputException {
        return new ConfigLoader(path.toString(), read(path)).error(key, problem);
    }

    /** Parses config text; {@code file} names it in messages. */
    public static Config parse(String file, String text) throws InputException {
        return new ConfigLoader(file, text).config();
    }

    private Config config() throws InputException {
        InputException unknown = null;
        for (String key : entries.keySet()) {
            if (!KEYS.contains(key)) {
                InputException e = error(key, "unknown key " + InputException.quote(key) + Suggestions.hint(key, KEYS));
                if (unknown == null || e.line() < unknown.line()) { // report the first in the file
                    unknown = e;
                }
            }
        }
        if (unknown != null) {
            throw unknown;
        }
        Config d = Config.defaults();
        Limits limits = limits(d.limits());
        boolean debug = bool("debug", d.debug());
        double epsilon = positive("epsilon", d.epsilon());
        double displayScale = number("display_scale", d.displayScale(), 1, 64, "a number from 1 to 64");
        int divider = integer("screen_divider", d.screenDivider(), 1, 256);
        int height = integer("display_height", d.displayHeight(), 1, 65536);
        // the default depth yields to a lower max_recursion; a depth the file sets must be within it
        int depth = integer("recursion_max", Math.min(d.recursionMax(), limits.maxRecursion()), 1, limits.maxRecursion());
        int width = integer("display_width", d.displayWidth(), 1, 65536);
        String name = entries.containsKey("name") ? value("name") : d.name();
        String scene = entries.containsKey("scene") ? value("scene") : d.scene();
        if (scene.isEmpty()) {
            throw error("scene", "scene: expected a scene file path, got nothing");
        }
        int threads = integer("threads", d.threads(), 0, 1024);
        Shading shading = shading(d.shading());
        LightTransport transport = transport(d.transport());
        if (transport.physical() && shading == Shading.PHONG) {
            throw error("integrator", Flags.PATH_NEEDS_COOK_TORRANCE);
        }
        int samples = samples(d.samples());
        double noise = noise(d.noise());
        int maxSamples = integer("max_samples", d.maxSamples(), 1, MAX_SAMPLES);
        double minWeight = number("min_weight", d.minWeight(), 0, 1, "a number from 0 to 1");
        double moveSpeed = positive("move_speed", d.moveSpeed());
        double turnSpeed = positive("turn_speed", d.turnSpeed());
        double targetFps = number("target_fps", d.targetFps(), 1, 1000, "a number from 1 to 1000");
        boolean freeFlight = bool("free_flight", d.freeFlight());
        ViewTransform view = new ViewTransform(number("exposure", d.view().exposure(), -ViewTransform.MAX_EXPOSURE,
                ViewTransform.MAX_EXPOSURE, "a number of stops from -16 to 16"), tone(d.view().tone()));
        // a size beyond the limit is refused on the settings a scene is rendered with, where a render: block or a
        // flag may have set another (Config.sizeRefusal), at the line that set it
        return new Config(debug, epsilon, displayScale, divider, width, height, depth, name, scene, threads,
                shading, samples, minWeight, moveSpeed, turnSpeed, targetFps, limits, freeFlight, transport, view,
                noise, maxSamples, sizePlace());
    }

    /**
     * Where an image too large is refused: the size where the file sets it, else the limit that the defaults
     * break; null when the file sets neither.
     */
    private Config.Place sizePlace() {
        for (String key : List.of("display_width", "display_height", "max_image_pixels")) {
            PropertiesText.Entry e = entries.get(key);
            if (e != null) {
                return new Config.Place(file, e.line(), e.column());
            }
        }
        return null;
    }

    private Limits limits(Limits d) throws InputException {
        long pixels = longInteger("max_image_pixels", d.maxImagePixels(), 1, Limits.MAX_IMAGE_PIXELS);
        long sceneBytes = longInteger("max_scene_bytes", d.maxSceneBytes(), 1, 1L << 30);
        int objects = integer("max_objects", d.maxObjects(), 0, 10_000_000);
        int lights = integer("max_lights", d.maxLights(), 0, 100_000);
        int recursion = integer("max_recursion", d.maxRecursion(), 1, Limits.MAX_RECURSION);
        return new Limits(pixels, sceneBytes, objects, lights, recursion);
    }

    private long longInteger(String key, long fallback, long min, long max) throws InputException {
        String v = value(key);
        if (v == null) {
            return fallback;
        }
        if (WHOLE.matcher(v).matches()) {
            try {
                long n = Long.parseLong(v);
                if (n >= min && n <= max) {
                    return n;
                }
            } catch (NumberFormatException e) {
                // beyond a long: reported below
            }
        }
        throw error(key, key + ": expected a whole number from " + min + " to " + max + ", got " + InputException.quote(v));
    }

    private String value(String key) {
        PropertiesText.Entry e = entries.get(key);
        return e == null ? null : e.value().trim();
    }

    private boolean bool(String key, boolean fallback) throws InputException {
        String v = value(key);
        if (v == null) {
            return fallback;
        }
        if (v.equalsIgnoreCase("true") || v.equalsIgnoreCase("false")) {
            return Boolean.parseBoolean(v);
        }
        throw error(key, key + ": expected true or false, got " + InputException.quote(v));
    }

    private int integer(String key, int fallback, int min, int max) throws InputException {
        String v = value(key);
        if (v == null) {
            return fallback;
        }
        if (WHOLE.matcher(v).matches()) {
            long n = Long.parseLong(v);
            if (n >= min && n <= max) {
                return (int) n;
            }
        }
        throw error(key, key + ": expected a whole number from " + min + " to " + max + ", got " + InputException.quote(v));
    }

    private double positive(String key, double fallback) throws InputException {
        return number(key, fallback, Double.MIN_VALUE, Double.MAX_VALUE, "a positive number");
    }

    private double number(String key, double fallback, double min, double max, String expected)
            throws InputException {
        String v = value(key);
        if (v == null) {
            return fallback;
        }
        if (DECIMAL.matcher(v).matches()) {
            double x = Double.parseDouble(v);
            if (Double.isFinite(x) && x >= min && x <= max) {
                return x;
            }
        }
        throw error(key, key + ": expected " + expected + ", got " + InputException.quote(v));
    }

    private Shading shading(Shading fallback) throws InputException {
        String v = value("shading");
        if (v == null) {
            return fallback;
        }
        Shading s = Shading.byKey(v);
        if (s == null) {
            throw error("shading", "shading: unknown model " + InputException.quote(v)
                    + Suggestions.hint(v, List.of("cook-torrance", "phong")));
        }
        return s;
    }

    private LightTransport transport(LightTransport fallback) throws InputException {
        String v = value("integrator");
        if (v == null) {
            return fallback;
        }
        LightTransport t = LightTransport.byKey(v);
        if (t == null) {
            throw error("integrator", "integrator: unknown integrator " + InputException.quote(v) + ", expected "
                    + LightTransport.IN_WORDS + Suggestions.hint(v, LightTransport.KEYS));
        }
        return t;
    }

    private ViewTransform.Tone tone(ViewTransform.Tone fallback) throws InputException {
        String v = value("tone");
        if (v == null) {
            return fallback;
        }
        ViewTransform.Tone t = ViewTransform.Tone.byKey(v);
        if (t == null) {
            throw error("tone", "tone: unknown tone curve " + InputException.quote(v)
                    + Suggestions.hint(v, ViewTransform.Tone.KEYS));
        }
        return t;
    }

    /** The largest {@code max_samples}: the window's longest refinement before adaptive sampling. */
    static final int MAX_SAMPLES = 65536;

    /** What {@code noise} accepts, in words (the config, a scene's render: block, {@code --noise}). */
    public static final String NOISE_RANGE = "0 (off) or a number from 0.0001 to 1";

    /** Whether {@code noise} may be {@code threshold}: 0, or from 1e-4 (0.01 %) to 1 (100 %). */
    public static boolean noiseInRange(double threshold) {
        return threshold == 0 || (threshold >= 1e-4 && threshold <= 1);
    }

    private double noise(double fallback) throws InputException {
        String v = value("noise");
        if (v == null) {
            return fallback;
        }
        double x = number("noise", fallback, 0, 1, NOISE_RANGE);
        if (!noiseInRange(x)) {
            throw error("noise", "noise: expected " + NOISE_RANGE + ", got " + InputException.quote(v));
        }
        return x;
    }

    private int samples(int fallback) throws InputException {
        String v = value("samples");
        if (v == null) {
            return fallback;
        }
        int n = integer("samples", fallback, 1, 4096);
        if (!Config.isPerfectSquare(n)) {
            throw error("samples", "samples: expected a perfect square (1, 4, 9, 16, ...), got " + InputException.quote(v));
        }
        return n;
    }

    /** An error at the line and column where {@code key} is set (the last time); 0:0 when it is not set. */
    private InputException error(String key, String problem) {
        PropertiesText.Entry e = entries.get(key);
        return e == null ? new InputException(file, 0, 0, problem) : new InputException(file, e.line(), e.column(), problem);
    }
}
