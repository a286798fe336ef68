package glint.scene;

import glint.math.Vector3d;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A surface material. {@code type} is the name of its material type, which the registry turns into
 * behaviour. {@code color} is the matte albedo, the metal's reflectance at normal incidence (F0) or
 * the glass's transmission tint. {@code kd, ks, kt, shininess} are the phong model's coefficients,
 * which every material has; {@code parameters} are the values of its type's own keys, by key, in the
 * order its type reads them (a metal's {@code roughness}, a glass's {@code ior} and {@code roughness}).
 */
public record Material(String type, Vector3d color, double kd, double ks, double kt, double shininess,
                       Map<String, Double> parameters) {

    public Material {
        parameters = Collections.unmodifiableMap(new LinkedHashMap<>(parameters));
    }

    /** A material with only the phong coefficients: its type reads no key of its own. */
    public Material(String type, Vector3d color, double kd, double ks, double kt, double shininess) {
        this(type, color, kd, ks, kt, shininess, Map.of());
    }

    /** Whether the material has a value for its type's key {@code key}. */
    public boolean has(String key) {
        return parameters.containsKey(key);
    }

    /** The value of its type's key {@code key}, which the material must have. */
    public double parameter(String key) {
        Double value = parameters.get(key);
        if (value == null) {
            throw new IllegalArgumentException("a " + type + " material has no parameter " + key);
        }
        return value;
    }

    /** This material with {@code key} set to {@code value} (kept in its place, or added last). */
    public Material with(String key, double value) {
        Map<String, Double> all = new LinkedHashMap<>(parameters);
        all.put(key, value);
        return new Material(type, color, kd, ks, kt, shininess, all);
    }
}
