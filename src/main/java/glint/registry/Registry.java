package glint.registry;

import glint.scene.Light;
import java.util.ArrayList;
import java.util.List;

/**
 * The primitive kinds, material types and light types scene files may name, and what each
 * compiles to: the one registration the loader, the compiled scene and shading read. A compiled
 * scene keeps its primitives kind by kind in this order; the first material type is the default,
 * whose preset an object without a {@code material:} gets.
 */
public record Registry(List<ShapeType<?>> shapes, List<MaterialType> materials, List<LightType<?>> lights) {

    /** What Glint knows: spheres and planes; matte, metal and glass; point and directional lights. */
    public static final Registry STANDARD = new Registry(List.of(SphereType.TYPE, PlaneType.TYPE),
            List.of(MatteType.TYPE, MetalType.TYPE, GlassType.TYPE),
            List.of(PointLightType.TYPE, DirectionalLightType.TYPE));

    public Registry {
        shapes = List.copyOf(shapes);
        materials = List.copyOf(materials);
        lights = List.copyOf(lights);
        if (materials.isEmpty()) {
            throw new IllegalArgumentException("a registry needs a material type, the default one");
        }
    }

    /** This registry and one more primitive kind. */
    public Registry with(ShapeType<?> shape) {
        return new Registry(added(shapes, shape), materials, lights);
    }

    /** This registry and one more material type. */
    public Registry with(MaterialType material) {
        return new Registry(shapes, added(materials, material), lights);
    }

    /** This registry and one more light type. */
    public Registry with(LightType<?> light) {
        return new Registry(shapes, materials, added(lights, light));
    }

    /** The material type an object without a material gets the preset of: the first one. */
    public MaterialType defaultMaterial() {
        return materials.get(0);
    }

    /** The material type of this name, which this registry must know. */
    public MaterialType material(String name) {
        for (MaterialType type : materials) {
            if (type.name().equals(name)) {
                return type;
            }
        }
        throw new IllegalArgumentException("no material type is registered as " + name);
    }

    /** The type of a light this registry knows. */
    public LightType<?> typeOf(Light light) {
        for (LightType<?> type : lights) {
            if (type.holds(light)) {
                return type;
            }
        }
        throw new IllegalArgumentException("no light type is registered for " + light.getClass().getSimpleName());
    }

    private static <T> List<T> added(List<T> list, T item) {
        List<T> longer = new ArrayList<>(list);
        longer.add(item);
        return longer;
    }
}
