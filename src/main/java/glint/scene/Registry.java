package glint.scene;

import java.util.ArrayList;
import java.util.List;

/**
 * The primitive kinds, material types and light types scene files may name: the one registration
 * the loader, the compiled scene and shading read. A compiled scene keeps its primitives kind by
 * kind in this order.
 */
public record Registry(List<ShapeType<?>> shapes, List<MaterialType> materials, List<LightType<?>> lights) {

    /** What Glint knows: spheres and planes; matte, metal and glass; point and directional lights. */
    public static final Registry STANDARD = new Registry(List.of(Sphere.TYPE, Plane.TYPE),
            List.of(MaterialType.MATTE, MaterialType.METAL, MaterialType.GLASS),
            List.of(Light.Point.TYPE, Light.Directional.TYPE));

    public Registry {
        shapes = List.copyOf(shapes);
        materials = List.copyOf(materials);
        lights = List.copyOf(lights);
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
