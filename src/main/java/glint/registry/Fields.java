package glint.registry;

import glint.input.InputException;
import glint.math.Vector3d;

/**
 * One object's, light's or material's mapping in a scene file, its keys already checked: what a
 * type's reader ({@link ShapeType}, {@link LightType}, {@link MaterialType}) reads its values from.
 * Each value is checked as it is read, and a bad one is reported at its line and column.
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

    /** A colour the mapping must have: three finite numbers, none negative. */
    Vector3d color(String key) throws InputException;

    /** Whether the mapping has {@code key}: a key it may leave out keeps a value the type gives. */
    boolean has(String key);

    /**
     * The value of {@code key} (which the mapping has) as written, for messages: "0" rather than
     * "0.0", cut after 60 characters as every value a message echoes.
     */
    String written(String key);

    /** An error about the value of {@code key} (which the mapping has), at its line and column. */
    InputException error(String key, String problem);
}
