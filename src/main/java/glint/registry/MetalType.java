package glint.registry;

import glint.math.Vector3d;
import glint.shading.Conductor;
import java.util.List;

/** {@code {type: metal, roughness: r}}: a conductor, scattered by {@link Conductor} (GGX of roughness r). */
public final class MetalType {

    public static final MaterialType TYPE = new MaterialType("metal", List.of("roughness"), new Conductor(),
            new Vector3d(0.9, 0.9, 0.9), 0.1, 0.7, 0.0, 50);

    private MetalType() {
    }
}
