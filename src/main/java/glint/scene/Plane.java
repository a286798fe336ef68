package glint.scene;

import glint.math.Vector3d;

/** An infinite two-sided plane through {@code point} with unit {@code normal}. */
public record Plane(Vector3d point, Vector3d normal) implements Shape {
}
