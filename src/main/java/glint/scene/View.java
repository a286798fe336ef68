package glint.scene;

/** A camera a scene lists under {@code views:}, which keys 1 to 9 of the window go to. */
public record View(String name, Camera camera) {
}
