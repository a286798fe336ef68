package glint.registry;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.shading.Conductor;
import glint.shading.MetalResponse;

/**
 * {@code {type: metal, roughness: r}}: a conductor, scattered by {@link Conductor} (GGX of
 * roughness r); it reads {@code roughness} besides the common keys, and compiles to its GGX alpha.
 */
public final class MetalType {

    public static final MaterialType TYPE = new MaterialType("metal", new Conductor(), new MetalResponse(),
            new Vector3d(0.9, 0.9, 0.9), 0.1, 0.7, 0.0, 50)
            .reads("roughness", 0, MetalType::roughness)
            .compiledBy(m -> Conductor.parameters(m.parameter("roughness")))
            .sampledAt("roughness", 0, 0.2, 0.5, 1);

    private MetalType() {
    }

    /** A roughness, from 0 (a mirror) to 1: what any type that reads roughness may read it with. */
    public static double roughness(Fields fields, String key) throws InputException {
        double roughness = fields.number(key);
        if (roughness < 0 || roughness > 1) {
            throw fields.error(key, key + " must lie in [0, 1], got " + fields.written(key));
        }
        return roughness;
    }
}
