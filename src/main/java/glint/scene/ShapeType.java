package glint.scene;

import glint.geometry.PrimitiveKind;
import glint.input.InputException;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;

/**
 * A kind of primitive, registered once in {@link Registry}: how scene files write one (its
 * {@code type:} name and its keys besides {@code type} and {@code material}), the shape that
 * reading one gives, and the primitive kind a scene's shapes of this type compile to.
 */
public record ShapeType<S extends Shape>(String name, Class<S> shapeClass, List<String> keys,
                                         Reader<S> reader, Function<List<S>, PrimitiveKind> compiler) {

    public ShapeType {
        keys = List.copyOf(keys);
    }

    /** Reads one shape from its mapping's values. */
    @FunctionalInterface
    public interface Reader<S> {
        S read(Fields fields) throws InputException;
    }

    /** Whether {@code shape} is of this type. */
    public boolean holds(Shape shape) {
        return shapeClass.isInstance(shape);
    }

    /** All of a scene's shapes of this type (in their order) as one primitive kind, in flat arrays. */
    public PrimitiveKind compile(List<? extends Shape> shapes) {
        List<S> typed = new ArrayList<>(shapes.size());
        for (Shape shape : shapes) {
            typed.add(shapeClass.cast(shape));
        }
        return compiler.apply(typed);
    }
}
