package glint.registry;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.shading.Dielectric;
import glint.shading.GlassResponse;

/**
 * {@code {type: glass, ior: n, roughness: r}}: a dielectric, scattered by {@link Dielectric} (index of
 * refraction n, smooth at roughness 0, frosted above); it reads {@code ior} and {@code roughness}
 * besides the common keys, and compiles to its ior and GGX alpha.
 */
public final class GlassType {

    public static final MaterialType TYPE = new MaterialType("glass", new Dielectric(), new GlassResponse(),
            Vector3d.ONE, 0.01, 0.2, 0.79, 125)
            .reads("ior", 1.5, GlassType::ior)
            .reads("roughness", 0, MetalType::roughness)
            .compiledBy(m -> Dielectric.parameters(m.parameter("ior"), m.parameter("roughness")))
            .sampledAt("ior", 0.75, 1.5, 2.4)
            .sampledAt("roughness", 0, 0.2, 0.5, 1);

    /** The range of ior: far wider than that of real media (about 1 to 4) and their ratios. */
    static final double MIN_IOR = 0.1, MAX_IOR = 100;

    private GlassType() {
    }

    /** An index of refraction: what any type that reads ior may read it with. */
    public static double ior(Fields fields, String key) throws InputException {
        double ior = fields.number(key);
        if (!(ior > 0)) {
            throw fields.error(key, key + " must be > 0, got " + fields.written(key));
        }
        if (ior < MIN_IOR || ior > MAX_IOR) {
            throw fields.error(key, key + " must lie between 0.1 and 100 (water is 1.33, glass 1.5, diamond 2.4), got "
                    + fields.written(key));
        }
        return ior;
    }
}
