package glint.recipe;

import glint.math.Vector3d;
import glint.scene.Shape;

/**
 * A shape of the scene model added by the kind recipe of docs/architecture.md, in test sources
 * only: a flat disc, plain data. {@link DiscType} registers it.
 */
public record Disc(Vector3d center, Vector3d normal, double radius) implements Shape {
}
