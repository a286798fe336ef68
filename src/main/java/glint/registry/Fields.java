package glint.registry;

import glint.input.InputException;
import glint.math.Vector3d;

/**
 * One object's or light's mapping in a scene file, its keys already checked: what a type's reader
 * ({@link ShapeType}, {@link LightType}) reads its values from. Each value is checked as it is read,
 * and a bad one is reported at its line and column.
 */
public interface Fields {

    /** A vector the mapping must have, such as a centre or a position. */
    Vector3d vector(String key) throws InputException;

    /** A unit direction the mapping must have: any vector but zero, normalised. */
    Vector3d direction(String key) throws InputException;

    /**
     * A length the mapping must have, such as a radius: above 0, between 1e-150 and 1e150, so its
     * square is a normal double and intersections neither underflow nor overflow.
     */
    double length(String key) throws InputException;

    /** A number the mapping must have. */
    double number(String key) throws InputException;

    /** An error about the value of {@code key} (which the mapping has), at its line and column. */
    InputException error(String key, String problem);
}
