package glint.scene;

import glint.math.Vector3d;

/**
 * A surface material. {@code color} is the matte albedo, the metal's reflectance at normal
 * incidence (F0) or the glass's transmission tint. {@code kd, ks, kt, shininess} are the phong
 * model's coefficients; {@code ior} and {@code roughness} are physical parameters.
 */
public record Material(MaterialType type, Vector3d color, double kd, double ks, double kt,
                       double shininess, double ior, double roughness) {

    /** The preset of a type (SPEC section 2 and the phong table of section 4). */
    public static Material preset(MaterialType type) {
        return switch (type) {
            case MATTE -> new Material(type, new Vector3d(0.8, 0.8, 0.8), 0.99, 0.01, 0.0, 10, 1.5, 0);
            case METAL -> new Material(type, new Vector3d(0.9, 0.9, 0.9), 0.1, 0.7, 0.0, 50, 1.5, 0);
            case GLASS -> new Material(type, Vector3d.ONE, 0.01, 0.2, 0.79, 125, 1.5, 0);
        };
    }
}
