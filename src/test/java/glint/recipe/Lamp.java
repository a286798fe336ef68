package glint.recipe;

import glint.math.Vector3d;
import glint.scene.Light;

/**
 * A light of the scene model added by the light recipe of docs/architecture.md, in test sources
 * only: a lamp at a point whose irradiance does not fall off with distance; plain data.
 * {@link LampType} registers it.
 */
record Lamp(Vector3d position, Vector3d color, double intensity) implements Light {
}
