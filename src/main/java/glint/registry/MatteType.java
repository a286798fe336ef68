package glint.registry;

import glint.math.Vector3d;
import glint.shading.Lambert;
import glint.shading.MatteResponse;

/** {@code {type: matte}}: a diffuse surface, scattered by {@link Lambert}; it reads the common keys only. */
public final class MatteType {

    public static final MaterialType TYPE = new MaterialType("matte", new Lambert(), new MatteResponse(),
            new Vector3d(0.8, 0.8, 0.8), 0.99, 0.01, 0.0, 10);

    private MatteType() {
    }
}
