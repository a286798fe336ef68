package glint.registry;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.scene.Material;
import glint.shading.Bsdf;
import glint.shading.Materials;
import glint.shading.WhittedResponse;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A kind of material, registered once in {@link Registry}: its name in scene files (also the name
 * of its preset material), the keys a material of the type reads and its reader, the preset's
 * values, its {@link Bsdf}, how the physically based model scatters light at it, and its
 * {@link WhittedResponse}, what Whitted's shading models ask of it besides. Every type
 * reads the colour and the phong coefficients ({@link #COMMON_KEYS}) over its preset, because the
 * phong model reads kd, ks, kt and shininess of every material whatever its type and refracts any
 * material with kt above 0 (at its ior, the preset's 1.5 unless the type reads {@code ior}); a
 * type's reader reads besides the physical parameters its BSDF uses, each checked against its range,
 * and the type compiles a material into the numbers its BSDF reads ({@link #compiledBy}, {@link #compile}).
 */
public final class MaterialType {

    /** The keys every material type reads. */
    public static final List<String> COMMON_KEYS = List.of("color", "kd", "ks", "kt", "shininess");
    /** The physical parameters a material has, which a type reads only when its BSDF uses them. */
    public static final List<String> PHYSICAL_KEYS = List.of("ior", "roughness");
    /**
     * The largest colour component and kd, ks and kt: shares of the light a surface sends back (1 is
     * all of it), allowed above 1 up to 1e30, the bound of every colour and light of a scene.
     */
    public static final double MAX_SHARE = 1e30;
    /**
     * The largest phong highlight exponent: (r.v)^shininess stays within rounding of 1 where r.v is
     * a rounding above 1 (at 1e20, 1 + 1e-16 would give infinity).
     */
    public static final double MAX_SHININESS = 1e6;

    private final String name;
    private final List<String> keys;
    private final Reader reader;
    /** The numbers its BSDF reads of a material; null: none. */
    private final Compiler compiler;
    private final Bsdf bsdf;
    private final WhittedResponse response;
    private final Material preset;
    /** Per physical key: the values the contract tests sample a material of the type at ({@link #samples}). */
    private final Map<String, double[]> sampleValues;

    /** Reads the physical parameters a type reads from a material's mapping. */
    @FunctionalInterface
    public interface Reader {
        /**
         * The material of the mapping: {@code common} is the type's preset with the mapping's common
         * keys read over it; a key the mapping leaves out keeps its value.
         */
        Material read(Fields fields, Material common) throws InputException;
    }

    /** Compiles a material of a type into the numbers its BSDF reads ({@link Materials#parameter}). */
    @FunctionalInterface
    public interface Compiler {
        double[] compile(Material material);
    }

    /**
     * A type that reads the common keys and {@code physicalKeys} (some of {@link #PHYSICAL_KEYS})
     * with {@code reader}, whose preset has the given colour and phong coefficients, ior 1.5 and
     * roughness 0.
     */
    public MaterialType(String name, List<String> physicalKeys, Reader reader, Bsdf bsdf, WhittedResponse response,
                        Vector3d color, double kd, double ks, double kt, double shininess) {
        if (!PHYSICAL_KEYS.containsAll(physicalKeys)) {
            throw new IllegalArgumentException("material type " + name + " reads " + physicalKeys
                    + ", but a material's physical parameters are " + PHYSICAL_KEYS);
        }
        List<String> all = new ArrayList<>(COMMON_KEYS);
        all.addAll(physicalKeys);
        this.name = name;
        this.keys = List.copyOf(all);
        this.reader = reader;
        this.bsdf = bsdf;
        this.response = response;
        this.preset = new Material(name, color, kd, ks, kt, shininess, 1.5, 0);
        this.sampleValues = Map.of();
        this.compiler = null;
    }

    private MaterialType(MaterialType type, Map<String, double[]> sampleValues, Compiler compiler) {
        name = type.name;
        keys = type.keys;
        reader = type.reader;
        this.compiler = compiler;
        bsdf = type.bsdf;
        response = type.response;
        preset = type.preset;
        this.sampleValues = sampleValues;
    }

    /** A type that reads the common keys only. */
    public MaterialType(String name, Bsdf bsdf, WhittedResponse response, Vector3d color, double kd, double ks,
                        double kt, double shininess) {
        this(name, List.of(), (fields, common) -> common, bsdf, response, color, kd, ks, kt, shininess);
    }

    /**
     * This type, sampled at {@code values} of its physical key {@code key} (within the key's range: its
     * ends and values between, where its BSDF changes kind or shape) by the tests every registered type
     * gets ({@code glint.shading.BsdfContractTest}); a type declares them for each physical key it reads.
     */
    public MaterialType sampledAt(String key, double... values) {
        if (!keys.contains(key) || COMMON_KEYS.contains(key) || values.length == 0) {
            throw new IllegalArgumentException("material type " + name + " cannot be sampled at " + key
                    + ": not a physical key it reads, or no values");
        }
        Map<String, double[]> all = new LinkedHashMap<>(sampleValues);
        all.put(key, values.clone());
        return new MaterialType(this, all, compiler);
    }

    /** This type, compiling a material into the numbers its BSDF reads with {@code compiler} (a metal: its alpha). */
    public MaterialType compiledBy(Compiler compiler) {
        return new MaterialType(this, sampleValues, compiler);
    }

    /**
     * A material of this type as the compiled scene keeps it: the type's BSDF and response, the
     * colour and phong's coefficients, and the numbers its BSDF reads.
     */
    public Materials.Material compile(Material m) {
        if (!m.type().equals(name)) {
            throw new IllegalArgumentException("a " + m.type() + " material is not of type " + name);
        }
        double[] numbers = compiler == null ? new double[0] : compiler.compile(m);
        return new Materials.Material(bsdf, response, m.color(), m.kd(), m.ks(), m.kt(), m.shininess(), m.ior(),
                numbers);
    }

    /** The physical keys this type reads ({@link #keys} besides the common ones). */
    public List<String> physicalKeys() {
        return keys.subList(COMMON_KEYS.size(), keys.size());
    }

    /** The values {@link #sampledAt} declared for physical key {@code key}; empty if none. */
    public double[] sampleValues(String key) {
        double[] values = sampleValues.get(key);
        return values == null ? new double[0] : values.clone();
    }

    /**
     * The materials the contract tests sample: the preset with every combination of the declared
     * values of its physical keys (the preset alone for a type that reads none).
     */
    public List<Material> samples() {
        List<Material> samples = List.of(preset);
        for (String key : physicalKeys()) {
            List<Material> next = new ArrayList<>();
            for (Material m : samples) {
                for (double v : sampleValues(key)) {
                    next.add(with(m, key, v));
                }
            }
            samples = next;
        }
        return samples;
    }

    private static Material with(Material m, String key, double value) {
        return switch (key) {
            case "ior" -> new Material(m.type(), m.color(), m.kd(), m.ks(), m.kt(), m.shininess(), value,
                    m.roughness());
            case "roughness" -> new Material(m.type(), m.color(), m.kd(), m.ks(), m.kt(), m.shininess(), m.ior(),
                    value);
            default -> throw new IllegalArgumentException("no physical key " + key);
        };
    }

    /** The name used in scene files. */
    public String name() {
        return name;
    }

    /** The keys a material of this type reads besides {@code type}: the common ones, then its physical ones. */
    public List<String> keys() {
        return keys;
    }

    public Bsdf bsdf() {
        return bsdf;
    }

    /** What Whitted's shading models ask of a material of this type besides its BSDF. */
    public WhittedResponse response() {
        return response;
    }

    /** The material its name alone means; a material of this type written in a scene starts from it. */
    public Material preset() {
        return preset;
    }

    /**
     * The material of a mapping of this type, whose keys are among {@link #keys}: the preset, the
     * common keys read over it (colour, then kd, ks, kt and shininess), then the type's own.
     */
    public Material read(Fields fields) throws InputException {
        Vector3d color = fields.has("color") ? color(fields) : preset.color();
        double kd = share(fields, "kd", preset.kd());
        double ks = share(fields, "ks", preset.ks());
        double kt = share(fields, "kt", preset.kt());
        double shininess = shininess(fields, preset.shininess());
        return reader.read(fields, new Material(name, color, kd, ks, kt, shininess, preset.ior(), preset.roughness()));
    }

    private static Vector3d color(Fields fields) throws InputException {
        Vector3d c = fields.color("color");
        if (c.maxComponent() > MAX_SHARE) {
            throw fields.error("color", "color must be at most 1e30 in each component, got "
                    + InputException.beyond(c.maxComponent(), MAX_SHARE, 3) + " (a material's color is the share of "
                    + "the light it sends back, 1 for all of it)");
        }
        return c;
    }

    /** kd, ks or kt: from 0 to {@link #MAX_SHARE}. */
    private static double share(Fields fields, String key, double fallback) throws InputException {
        double value = atLeastZero(fields, key, fallback);
        if (value > MAX_SHARE) {
            throw fields.error(key, key + " must be at most 1e30, got " + fields.written(key)
                    + " (the share of the light it sends back, 1 for all of it)");
        }
        return value;
    }

    private static double shininess(Fields fields, double fallback) throws InputException {
        double value = atLeastZero(fields, "shininess", fallback);
        if (value > MAX_SHININESS) {
            throw fields.error("shininess", "shininess must be at most 1e6, got " + fields.written("shininess")
                    + " (the highlight's exponent: 10 is broad, 1000 a point)");
        }
        return value;
    }

    private static double atLeastZero(Fields fields, String key, double fallback) throws InputException {
        if (!fields.has(key)) {
            return fallback;
        }
        double value = fields.number(key);
        if (value < 0) {
            throw fields.error(key, key + " must be >= 0, got " + fields.written(key));
        }
        return value;
    }

    @Override
    public String toString() {
        return name;
    }
}
