package glint.recipe;

import glint.math.Vector3d;
import glint.registry.MaterialType;

/**
 * The registration of the glowing material: {@code {type: glow, color: [r, g, b]}}, scattered by
 * {@link Glow}; it reads the common keys only, and its preset glows white.
 */
final class GlowType {

    static final MaterialType TYPE = new MaterialType("glow", new Glow(), Vector3d.ONE, 0, 0, 0, 1);

    private GlowType() {
    }
}
