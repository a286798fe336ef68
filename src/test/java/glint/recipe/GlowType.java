package glint.recipe;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.registry.Fields;
import glint.registry.MaterialType;
import glint.shading.WhittedResponse;

/**
 * The registration of the glowing material: {@code {type: glow, color: [r, g, b], strength: s}},
 * scattered by {@link Glow}; besides the common keys it reads a key of its own, which no shipped type
 * has, {@code strength} (from 0 to 1e30, 1 unless written), and compiles to it (the values of its own
 * keys, in order, as a type without a compile function does). Its preset glows white. To Whitted's
 * models it sends no single rays on, and neither ambient light nor phong's shadow rays apply to it (the
 * response's defaults).
 */
public final class GlowType {

    static final WhittedResponse NO_RAYS = (m, s, out) -> {
        out.setReflect(0, 0, 0);
        out.setTransmit(0, 0, 0);
    };

    public static final MaterialType TYPE = new MaterialType("glow", new Glow(), NO_RAYS, Vector3d.ONE, 0, 0, 0, 1)
            .reads("strength", 1, GlowType::strength)
            .sampledAt("strength", 0, 1, 4);

    private GlowType() {
    }

    /** How many times its colour it glows: from 0 (dark) to 1e30. */
    private static double strength(Fields fields, String key) throws InputException {
        double strength = fields.number(key);
        if (!(strength >= 0 && strength <= MaterialType.MAX_SHARE)) {
            throw fields.error(key, key + " must lie in [0, 1e30], got " + fields.written(key));
        }
        return strength;
    }
}
