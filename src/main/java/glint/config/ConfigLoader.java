package glint.config;

import glint.input.InputException;
import glint.input.Suggestions;
import java.io.IOException;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Properties;
import java.util.Set;

/** Reads config.properties; every key is optional, and a bad one is reported with its line. */
public final class ConfigLoader {

    static final Set<String> KEYS = new LinkedHashSet<>(List.of(
            "debug", "epsilon", "display_scale", "screen_divider", "display_height", "recursion_max",
            "display_width", "name", "scene", "threads", "shading", "samples", "min_weight",
            "move_speed", "turn_speed", "target_fps", "free_flight",
            "max_image_pixels", "max_scene_bytes", "max_objects", "max_lights", "max_recursion"));

    private final String file;
    private final List<String> lines;
    private final Properties properties;

    private ConfigLoader(String file, String text) throws InputException {
        this.file = file;
        this.lines = text.lines().toList();
        this.properties = new Properties();
        try {
            properties.load(new StringReader(text));
        } catch (IOException | IllegalArgumentException e) {
            throw new InputException(file, 0, 0, "not a properties file: " + e.getMessage());
        }
    }

    /** Loads a config file. */
    public static Config load(Path path) throws InputException {
        String text;
        try {
            text = Files.readString(path, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new InputException(path.toString(), 0, 0, "no such file");
        } catch (IOException e) {
            throw new InputException(path.toString(), 0, 0, "cannot read: " + e.getMessage());
        }
        return parse(path.toString(), text);
    }

    /** Parses config text; {@code file} names it in messages. */
    public static Config parse(String file, String text) throws InputException {
        return new ConfigLoader(file, text).config();
    }

    private Config config() throws InputException {
        InputException unknown = null;
        for (String key : properties.stringPropertyNames()) {
            if (!KEYS.contains(key)) {
                InputException e = error(key, "unknown key '" + key + "'" + Suggestions.hint(key, KEYS));
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
        int depth = integer("recursion_max", d.recursionMax(), 1, limits.maxRecursion());
        int width = integer("display_width", d.displayWidth(), 1, 65536);
        String sizeProblem = limits.imageSizeProblem(width, height);
        if (sizeProblem != null) {
            throw error(properties.containsKey("display_width") ? "display_width" : "display_height",
                    "display_width x display_height: " + sizeProblem);
        }
        String name = properties.getProperty("name", d.name()).trim();
        String scene = properties.getProperty("scene", d.scene()).trim();
        if (scene.isEmpty()) {
            throw error("scene", "scene: expected a scene file path, got nothing");
        }
        int threads = integer("threads", d.threads(), 0, 1024);
        Shading shading = shading(d.shading());
        int samples = samples(d.samples());
        double minWeight = number("min_weight", d.minWeight(), 0, 1, "a number from 0 to 1");
        double moveSpeed = positive("move_speed", d.moveSpeed());
        double turnSpeed = positive("turn_speed", d.turnSpeed());
        double targetFps = number("target_fps", d.targetFps(), 1, 1000, "a number from 1 to 1000");
        boolean freeFlight = bool("free_flight", d.freeFlight());
        return new Config(debug, epsilon, displayScale, divider, width, height, depth, name, scene, threads,
                shading, samples, minWeight, moveSpeed, turnSpeed, targetFps, limits, freeFlight);
    }

    private Limits limits(Limits d) throws InputException {
        long pixels = longInteger("max_image_pixels", d.maxImagePixels(), 1, 1L << 31);
        long sceneBytes = longInteger("max_scene_bytes", d.maxSceneBytes(), 1, 1L << 30);
        int objects = integer("max_objects", d.maxObjects(), 0, 10_000_000);
        int lights = integer("max_lights", d.maxLights(), 0, 100_000);
        int recursion = integer("max_recursion", d.maxRecursion(), 1, 1024);
        return new Limits(pixels, sceneBytes, objects, lights, recursion);
    }

    private long longInteger(String key, long fallback, long min, long max) throws InputException {
        String v = value(key);
        if (v == null) {
            return fallback;
        }
        try {
            long n = Long.parseLong(v);
            if (n >= min && n <= max) {
                return n;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw error(key, key + ": expected a whole number from " + min + " to " + max + ", got '" + v + "'");
    }

    private String value(String key) {
        String v = properties.getProperty(key);
        return v == null ? null : v.trim();
    }

    private boolean bool(String key, boolean fallback) throws InputException {
        String v = value(key);
        if (v == null) {
            return fallback;
        }
        if (v.equalsIgnoreCase("true") || v.equalsIgnoreCase("false")) {
            return Boolean.parseBoolean(v);
        }
        throw error(key, key + ": expected true or false, got '" + v + "'");
    }

    private int integer(String key, int fallback, int min, int max) throws InputException {
        String v = value(key);
        if (v == null) {
            return fallback;
        }
        try {
            int n = Integer.parseInt(v);
            if (n >= min && n <= max) {
                return n;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw error(key, key + ": expected a whole number from " + min + " to " + max + ", got '" + v + "'");
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
        try {
            double x = Double.parseDouble(v);
            if (Double.isFinite(x) && x >= min && x <= max && !v.endsWith("d") && !v.endsWith("f")
                    && !v.endsWith("D") && !v.endsWith("F")) {
                return x;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw error(key, key + ": expected " + expected + ", got '" + v + "'");
    }

    private Shading shading(Shading fallback) throws InputException {
        String v = value("shading");
        if (v == null) {
            return fallback;
        }
        Shading s = Shading.byKey(v);
        if (s == null) {
            throw error("shading", "shading: unknown model '" + v + "'"
                    + Suggestions.hint(v, List.of("cook-torrance", "phong")));
        }
        return s;
    }

    private int samples(int fallback) throws InputException {
        String v = value("samples");
        if (v == null) {
            return fallback;
        }
        int n = integer("samples", fallback, 1, 4096);
        if (!Config.isPerfectSquare(n)) {
            throw error("samples", "samples: expected a perfect square (1, 4, 9, 16, ...), got '" + v + "'");
        }
        return n;
    }

    /**
     * An error at the line where {@code key} is set (line 0 when it cannot be found); when it is set
     * more than once, the last line, whose value is the one that counts.
     */
    private InputException error(String key, String problem) {
        for (int i = lines.size() - 1; i >= 0; i--) {
            String line = lines.get(i);
            String trimmed = line.stripLeading();
            if (trimmed.startsWith(key)) {
                String rest = trimmed.substring(key.length());
                if (rest.isEmpty() || "=: \t".indexOf(rest.charAt(0)) >= 0) {
                    return new InputException(file, i + 1, line.length() - trimmed.length() + 1, problem);
                }
            }
        }
        return new InputException(file, 0, 0, problem);
    }
}
