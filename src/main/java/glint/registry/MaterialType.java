package glint.registry;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.scene.Material;
import glint.shading.Bsdf;
import glint.shading.Materials;
import glint.shading.WhittedResponse;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A kind of material, registered once in {@link Registry}: its name in scene files (also the name
 * of its preset material), the keys a material of the type reads and how, the preset's values, what
 * a material of the type compiles to (the numbers its BSDF reads, {@link #compile}), its {@link Bsdf},
 * how the physically based model scatters light at it, and its {@link WhittedResponse}, what Whitted's
 * shading models ask of it besides. Every type reads the colour and the phong coefficients
 * ({@link #COMMON_KEYS}) over its preset, because the phong model reads kd, ks, kt and shininess of
 * every material whatever its type and refracts any material with kt above 0 (at its {@code ior}
 * where its type reads one, else at {@link #PHONG_IOR}); besides, a type reads keys of its own, the
 * parameters its BSDF uses ({@link #reads}), each read and checked by its own reader, and compiles a
 * material into the numbers its BSDF reads ({@link #compiledBy}).
 */
public final class MaterialType {

    /** The keys every material type reads. */
    public static final List<String> COMMON_KEYS = List.of("color", "kd", "ks", "kt", "shininess");
    /** The index the phong model refracts a material's kt at where its type reads no {@code ior}. */
    public static final double PHONG_IOR = 1.5;
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
    /** The common keys, then the type's own keys in the order it reads them. */
    private final List<String> keys;
    /** Per key of its own: how a mapping's value is read and checked. */
    private final Map<String, KeyReader> readers;
    /** The numbers its BSDF reads of a material; null: the values of its own keys, in their order. */
    private final Compiler compiler;
    private final Bsdf bsdf;
    private final WhittedResponse response;
    private final Material preset;
    /** Per key of its own: the values the contract tests sample a material of the type at ({@link #samples}). */
    private final Map<String, double[]> sampleValues;

    /** Reads one of a type's own keys from a material's mapping. */
    @FunctionalInterface
    public interface KeyReader {
        /**
         * The value of {@code key}, which the mapping has, checked against its range: a value out of it
         * is {@code fields.error(key, problem)}, showing {@code fields.written(key)}.
         */
        double read(Fields fields, String key) throws InputException;
    }

    /** Compiles a material of a type into the numbers its BSDF reads ({@link glint.shading.Materials#parameter}). */
    @FunctionalInterface
    public interface Compiler {
        double[] compile(Material material);
    }

    /**
     * A type that reads the common keys, whose preset has the given colour and phong coefficients, and
     * no key of its own yet ({@link #reads}).
     */
    public MaterialType(String name, Bsdf bsdf, WhittedResponse response, Vector3d color, double kd, double ks,
                        double kt, double shininess) {
        this(name, COMMON_KEYS, Map.of(), null, bsdf, response, new Material(name, color, kd, ks, kt, shininess),
                Map.of());
    }

    private MaterialType(String name, List<String> keys, Map<String, KeyReader> readers, Compiler compiler, Bsdf bsdf,
                         WhittedResponse response, Material preset, Map<String, double[]> sampleValues) {
        this.name = name;
        this.keys = List.copyOf(keys);
        this.readers = Collections.unmodifiableMap(new LinkedHashMap<>(readers));
        this.compiler = compiler;
        this.bsdf = bsdf;
        this.response = response;
        this.preset = preset;
        this.sampleValues = Collections.unmodifiableMap(new LinkedHashMap<>(sampleValues));
    }

    /**
     * This type, reading besides key {@code key} of its own, with {@code reader}; its preset has
     * {@code presetValue}. A key may be any but {@code type}, the common ones and the type's others.
     */
    public MaterialType reads(String key, double presetValue, KeyReader reader) {
        if (key.equals("type") || keys.contains(key)) {
            boolean common = key.equals("type") || COMMON_KEYS.contains(key);
            throw new IllegalArgumentException("material type " + name + " cannot read " + key + " of its own: "
                    + (common ? "every type reads it" : "it reads it already"));
        }
        List<String> all = new ArrayList<>(keys);
        all.add(key);
        Map<String, KeyReader> allReaders = new LinkedHashMap<>(readers);
        allReaders.put(key, reader);
        return new MaterialType(name, all, allReaders, compiler, bsdf, response, preset.with(key, presetValue),
                sampleValues);
    }

    /**
     * This type, compiling a material into the numbers its BSDF reads with {@code compiler} (a metal:
     * its GGX alpha); without one a material compiles to the values of the type's own keys, in order.
     */
    public MaterialType compiledBy(Compiler compiler) {
        return new MaterialType(name, keys, readers, compiler, bsdf, response, preset, sampleValues);
    }

    /**
     * This type, sampled at {@code values} of its own key {@code key} (within the key's range: its
     * ends and values between, where its BSDF changes kind or shape) by the tests every registered type
     * gets ({@code glint.shading.BsdfContractTest}); a type declares them for each key of its own.
     */
    public MaterialType sampledAt(String key, double... values) {
        if (!readers.containsKey(key) || values.length == 0) {
            throw new IllegalArgumentException("material type " + name + " cannot be sampled at " + key
                    + ": not a key of its own, or no values");
        }
        Map<String, double[]> all = new LinkedHashMap<>(sampleValues);
        all.put(key, values.clone());
        return new MaterialType(name, keys, readers, compiler, bsdf, response, preset, all);
    }

    /** The keys of its own this type reads ({@link #keys} besides the common ones), in order. */
    public List<String> ownKeys() {
        return keys.subList(COMMON_KEYS.size(), keys.size());
    }

    /** The values {@link #sampledAt} declared for key {@code key}; empty if none. */
    public double[] sampleValues(String key) {
        double[] values = sampleValues.get(key);
        return values == null ? new double[0] : values.clone();
    }

    /**
     * The materials the contract tests sample: the preset with every combination of the declared
     * values of its own keys (the preset alone for a type that reads none).
     */
    public List<Material> samples() {
        List<Material> samples = List.of(preset);
        for (String key : ownKeys()) {
            List<Material> next = new ArrayList<>();
            for (Material m : samples) {
                for (double v : sampleValues(key)) {
                    next.add(m.with(key, v));
                }
            }
            samples = next;
        }
        return samples;
    }

    /**
     * A material of this type as the compiled scene keeps it: the type's BSDF and response, the
     * colour and phong's coefficients (its ior where it has one, else {@link #PHONG_IOR}), and the
     * numbers its BSDF reads.
     */
    public Materials.Material compile(Material m) {
        if (!m.type().equals(name)) {
            throw new IllegalArgumentException("a " + m.type() + " material is not of type " + name);
        }
        double[] numbers;
        if (compiler != null) {
            numbers = compiler.compile(m);
        } else {
            numbers = new double[ownKeys().size()];
            for (int k = 0; k < numbers.length; k++) {
                numbers[k] = m.parameter(ownKeys().get(k));
            }
        }
        double ior = m.has("ior") ? m.parameter("ior") : PHONG_IOR;
        return new Materials.Material(bsdf, response, m.color(), m.kd(), m.ks(), m.kt(), m.shininess(), ior, numbers);
    }

    /** The name used in scene files. */
    public String name() {
        return name;
    }

    /** The keys a material of this type reads besides {@code type}: the common ones, then its own. */
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
     * common keys read over it (colour, then kd, ks, kt and shininess), then the type's own, in order.
     */
    public Material read(Fields fields) throws InputException {
        Vector3d color = fields.has("color") ? color(fields) : preset.color();
        double kd = share(fields, "kd", preset.kd());
        double ks = share(fields, "ks", preset.ks());
        double kt = share(fields, "kt", preset.kt());
        double shininess = shininess(fields, preset.shininess());
        Map<String, Double> parameters = new LinkedHashMap<>(preset.parameters());
        for (Map.Entry<String, KeyReader> key : readers.entrySet()) {
            if (fields.has(key.getKey())) {
                parameters.put(key.getKey(), key.getValue().read(fields, key.getKey()));
            }
        }
        return new Material(name, color, kd, ks, kt, shininess, parameters);
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
