package glint.scene;

import glint.math.Vector3d;

/**
 * A surface material. {@code type} is the name of its material type, which the registry turns into
 * behaviour. {@code color} is the matte albedo, the metal's reflectance at normal incidence (F0) or
 * the glass's transmission tint. {@code kd, ks, kt, shininess} are the phong model's coefficients;
 * {@code ior} and {@code roughness} are physical parameters.
 */
public record Material(String type, Vector3d color, double kd, double ks, double kt,
                       double shininess, double ior, double roughness) {
}
