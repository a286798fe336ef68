package glint.scene;

/** A geometric shape of the scene model: plain data, whose type's registration says how it is read and compiled. */
public interface Shape {
}
