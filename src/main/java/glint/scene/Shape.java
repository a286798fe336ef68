package glint.scene;

/** A geometric shape of the scene model; its {@link ShapeType} says how it is read and compiled. */
public interface Shape {
}
