package glint.registry;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.scene.Material;
import glint.shading.Conductor;
import glint.shading.MetalResponse;
import java.util.List;

/**
 * {@code {type: metal, roughness: r}}: a conductor, scattered by {@link Conductor} (GGX of
 * roughness r); it reads {@code roughness} besides the common keys, and compiles to its GGX alpha.
 */
public final class MetalType {

    public static final MaterialType TYPE = new MaterialType("metal", List.of("roughness"), MetalType::read,
            new Conductor(), new MetalResponse(), new Vector3d(0.9, 0.9, 0.9), 0.1, 0.7, 0.0, 50)
            .compiledBy(m -> Conductor.parameters(m.roughness()))
            .sampledAt("roughness", 0, 0.2, 0.5, 1);

    private MetalType() {
    }

    /**
     * The material with the mapping's roughness, when it has one: from 0 (a mirror) to 1; what any
     * type that reads roughness may read it with.
     */
    public static Material read(Fields fields, Material common) throws InputException {
        if (!fields.has("roughness")) {
            return common;
        }
        double roughness = fields.number("roughness");
        if (roughness < 0 || roughness > 1) {
            throw fields.error("roughness", "roughness must lie in [0, 1], got " + fields.written("roughness"));
        }
        return new Material(common.type(), common.color(), common.kd(), common.ks(), common.kt(), common.shininess(),
                common.ior(), roughness);
    }
}
