package glint.registry;

import glint.geometry.PrimitiveKind;
import glint.input.InputException;
import glint.scene.Shape;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import java.util.function.ToIntFunction;

/**
 * A kind of primitive, registered once in {@link Registry}: how scene files write one (its
 * {@code type:} name and its keys besides {@code type} and {@code material}), the shape that
 * reading one gives, the primitive kind a scene's shapes of this type compile to, and how many
 * primitives each shape compiles to (one, or for a shape made of many, such as a mesh, its count:
 * each of them gets the shape's material).
 */
public record ShapeType<S extends Shape>(String name, Class<S> shapeClass, List<String> keys,
                                         Reader<S> reader, Function<List<S>, PrimitiveKind> compiler,
                                         ToIntFunction<S> primitiveCount) {

    public ShapeType {
        keys = List.copyOf(keys);
    }

    /** A type whose shapes compile to one primitive each. */
    public ShapeType(String name, Class<S> shapeClass, List<String> keys, Reader<S> reader,
                     Function<List<S>, PrimitiveKind> compiler) {
        this(name, shapeClass, keys, reader, compiler, shape -> 1);
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

    /** How many primitives {@code shape}, of this type, compiles to. */
    public int primitives(Shape shape) {
        return primitiveCount.applyAsInt(shapeClass.cast(shape));
    }

    /**
     * All of a scene's shapes of this type (in their order) as one primitive kind, in flat arrays:
     * the primitives of each shape in turn.
     */
    public PrimitiveKind compile(List<? extends Shape> shapes) {
        List<S> typed = new ArrayList<>(shapes.size());
        int expected = 0;
        for (Shape shape : shapes) {
            typed.add(shapeClass.cast(shape));
            expected += primitives(shape);
        }
        PrimitiveKind kind = compiler.apply(typed);
        if (kind.count() != expected) {
            throw new IllegalStateException("the " + name + " kind holds " + kind.count()
                    + " primitives, but its shapes count " + expected);
        }
        return kind;
    }
}
