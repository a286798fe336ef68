package glint.scene;

import glint.math.Vector3d;

/**
 * A surface material. {@code color} is the matte albedo, the metal's reflectance at normal
 * incidence (F0) or the glass's transmission tint. {@code kd, ks, kt, shininess} are the phong
 * model's coefficients; {@code ior} and {@code roughness} are physical parameters.
 */
public record Material(MaterialType type, Vector3d color, double kd, double ks, double kt,
                       double shininess, double ior, double roughness) {
}
