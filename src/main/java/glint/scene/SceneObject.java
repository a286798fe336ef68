package glint.scene;

/** A shape with its material. */
public record SceneObject(Shape shape, Material material) {
}
