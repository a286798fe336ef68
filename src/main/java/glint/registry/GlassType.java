package glint.registry;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.scene.Material;
import glint.shading.Dielectric;
import glint.shading.GlassResponse;
import java.util.List;

/**
 * {@code {type: glass, ior: n, roughness: r}}: a dielectric, scattered by {@link Dielectric} (index of
 * refraction n, smooth at roughness 0, frosted above); it reads {@code ior} and {@code roughness}
 * besides the common keys, and compiles to its ior and GGX alpha.
 */
public final class GlassType {

    public static final MaterialType TYPE = new MaterialType("glass", List.of("ior", "roughness"),
            (fields, common) -> MetalType.read(fields, read(fields, common)), new Dielectric(), new GlassResponse(),
            Vector3d.ONE, 0.01, 0.2, 0.79, 125)
            .compiledBy(m -> Dielectric.parameters(m.ior(), m.roughness()))
            .sampledAt("ior", 0.75, 1.5, 2.4)
            .sampledAt("roughness", 0, 0.2, 0.5, 1);

    /** The range of ior: far wider than that of real media (about 1 to 4) and their ratios. */
    static final double MIN_IOR = 0.1, MAX_IOR = 100;

    private GlassType() {
    }

    /** The material with the mapping's ior, when it has one: what any type that reads ior may read it with. */
    public static Material read(Fields fields, Material common) throws InputException {
        if (!fields.has("ior")) {
            return common;
        }
        double ior = fields.number("ior");
        if (!(ior > 0)) {
            throw fields.error("ior", "ior must be > 0, got " + fields.written("ior"));
        }
        if (ior < MIN_IOR || ior > MAX_IOR) {
            throw fields.error("ior", "ior must lie between 0.1 and 100 (water is 1.33, glass 1.5, diamond 2.4), got "
                    + fields.written("ior"));
        }
        return new Material(common.type(), common.color(), common.kd(), common.ks(), common.kt(), common.shininess(),
                ior, common.roughness());
    }
}
