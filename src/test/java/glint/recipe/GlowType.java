package glint.recipe;

import glint.math.Vector3d;
import glint.registry.MaterialType;
import glint.shading.WhittedResponse;

/**
 * The registration of the glowing material: {@code {type: glow, color: [r, g, b]}}, scattered by
 * {@link Glow}; it reads the common keys only, and its preset glows white. To Whitted's models it sends
 * no single rays on, and neither ambient light nor phong's shadow rays apply to it (the response's
 * defaults).
 */
final class GlowType {

    static final WhittedResponse NO_RAYS = (m, s, out) -> {
        out.setReflect(0, 0, 0);
        out.setTransmit(0, 0, 0);
    };

    static final MaterialType TYPE = new MaterialType("glow", new Glow(), NO_RAYS, Vector3d.ONE, 0, 0, 0, 1);

    private GlowType() {
    }
}
