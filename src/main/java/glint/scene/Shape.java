package glint.scene;

/** The closed set of geometric shapes a scene can hold. */
public sealed interface Shape permits Sphere, Plane {
}
