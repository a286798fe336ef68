package glint.registry;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.scene.Light;
import glint.scene.Shape;
import glint.shading.Lights;
import java.util.List;
import java.util.function.Function;

/**
 * A kind of light, registered once in {@link Registry}: how scene files write one (its {@code type:}
 * name and its keys besides {@code type}, {@code color} and {@code intensity}), the light that
 * reading one gives, and what a light of the kind compiles to ({@link Compiled}: the sampler and
 * numbers shading reads, and the body rays meet, if it has one).
 */
public record LightType<L extends Light>(String name, Class<L> lightClass, List<String> keys, Reader<L> reader,
                                         Function<L, Compiled> compiler) {

    public LightType {
        keys = List.copyOf(keys);
    }

    /** Reads one light from its mapping's values; colour and intensity are read and checked already. */
    @FunctionalInterface
    public interface Reader<L> {
        L read(Fields fields, Vector3d color, double intensity) throws InputException;
    }

    /**
     * A light as the renderer keeps it: what shading samples ({@code light}), and where it has a body
     * that rays meet (a sphere light's sphere), that shape and the radiance its surface sends.
     */
    public record Compiled(Lights.Light light, Shape body, Vector3d bodyRadiance) {

        /** A light without a body. */
        public Compiled(Lights.Light light) {
            this(light, null, null);
        }
    }

    /** Whether {@code light} is of this type. */
    public boolean holds(Light light) {
        return lightClass.isInstance(light);
    }

    /** What {@code light}, of this type, compiles to. */
    public Compiled compile(Light light) {
        return compiler.apply(lightClass.cast(light));
    }
}
