package glint.recipe;

import glint.math.Vector3d;
import glint.scene.Shape;

/**
 * A shape made of many primitives, as a mesh is, added by the kind recipe in test sources only: a
 * row of {@code count} discs facing -z, the first at {@code first}, each next one {@code step} on;
 * plain data. {@link DiscRowType} registers it.
 */
record DiscRow(Vector3d first, Vector3d step, int count, double radius) implements Shape {
}
