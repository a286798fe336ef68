package glint.registry;

import glint.math.Vector3d;
import glint.shading.Dielectric;
import java.util.List;

/** {@code {type: glass, ior: n}}: a dielectric, scattered by {@link Dielectric} (index of refraction n). */
public final class GlassType {

    public static final MaterialType TYPE = new MaterialType("glass", List.of("ior"), new Dielectric(), Vector3d.ONE,
            0.01, 0.2, 0.79, 125);

    private GlassType() {
    }
}
