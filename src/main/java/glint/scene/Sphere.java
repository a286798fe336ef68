package glint.scene;

import glint.math.Vector3d;

/** A sphere; its normal points outward. */
public record Sphere(Vector3d center, double radius) implements Shape {
}
