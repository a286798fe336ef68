package glint.registry;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.scene.Light;
import glint.shading.LightSampler;
import java.util.List;
import java.util.function.Function;

/**
 * A kind of light, registered once in {@link Registry}: how scene files write one (its {@code type:}
 * name and its keys besides {@code type}, {@code color} and {@code intensity}), the light that
 * reading one gives, the vector the compiled scene keeps of it (a position or a direction), how
 * shading samples it, and whether all its light leaves one point (then its shadow rays may use
 * direction cells around that point).
 */
public record LightType<L extends Light>(String name, Class<L> lightClass, List<String> keys, Reader<L> reader,
                                         Function<L, Vector3d> vector, LightSampler sampler, boolean atPoint) {

    public LightType {
        keys = List.copyOf(keys);
    }

    /** Reads one light from its mapping's values; colour and intensity are read and checked already. */
    @FunctionalInterface
    public interface Reader<L> {
        L read(Fields fields, Vector3d color, double intensity) throws InputException;
    }

    /** Whether {@code light} is of this type. */
    public boolean holds(Light light) {
        return lightClass.isInstance(light);
    }

    /** The vector the compiled scene keeps of {@code light}, which the sampler reads. */
    public Vector3d vectorOf(Light light) {
        return vector.apply(lightClass.cast(light));
    }
}
