package glint.registry;

import glint.math.Vector3d;
import glint.scene.Material;
import glint.shading.Bsdf;
import java.util.ArrayList;
import java.util.List;

/**
 * A kind of material, registered once in {@link Registry}: its name in scene files (also the name
 * of its preset material), the keys a material of the type reads, the preset's values, and its
 * {@link Bsdf}, how the physically based model scatters light at it. Every type reads the colour
 * and the phong coefficients ({@link #COMMON_KEYS}), because the phong model reads kd, ks, kt and
 * shininess of every material whatever its type and refracts any material with kt above 0 (at its
 * ior, the preset's 1.5 unless the type reads {@code ior}); a type reads besides the physical
 * parameters its BSDF uses.
 */
public final class MaterialType {

    /** The keys every material type reads. */
    public static final List<String> COMMON_KEYS = List.of("color", "kd", "ks", "kt", "shininess");
    /** The physical parameters a material has, which a type reads only when its BSDF uses them. */
    public static final List<String> PHYSICAL_KEYS = List.of("ior", "roughness");

    private final String name;
    private final List<String> keys;
    private final Bsdf bsdf;
    private final Material preset;

    /**
     * A type that reads the common keys and {@code physicalKeys} (some of {@link #PHYSICAL_KEYS}),
     * whose preset has the given colour and phong coefficients, ior 1.5 and roughness 0.
     */
    public MaterialType(String name, List<String> physicalKeys, Bsdf bsdf, Vector3d color, double kd, double ks,
                        double kt, double shininess) {
        if (!PHYSICAL_KEYS.containsAll(physicalKeys)) {
            throw new IllegalArgumentException("material type " + name + " reads " + physicalKeys
                    + ", but a material's physical parameters are " + PHYSICAL_KEYS);
        }
        List<String> all = new ArrayList<>(COMMON_KEYS);
        all.addAll(physicalKeys);
        this.name = name;
        this.keys = List.copyOf(all);
        this.bsdf = bsdf;
        this.preset = new Material(name, color, kd, ks, kt, shininess, 1.5, 0);
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

    /** The material its name alone means; a material of this type written in a scene starts from it. */
    public Material preset() {
        return preset;
    }

    @Override
    public String toString() {
        return name;
    }
}
