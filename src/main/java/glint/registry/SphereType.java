package glint.registry;

import glint.geometry.SphereKind;
import glint.scene.Sphere;
import java.util.List;

/** {@code {type: sphere, center: [x, y, z], radius: r}}: a {@link Sphere}, compiled to a {@link SphereKind}. */
public final class SphereType {

    public static final ShapeType<Sphere> TYPE = new ShapeType<>("sphere", Sphere.class, List.of("center", "radius"),
            fields -> new Sphere(fields.vector("center"), fields.length("radius")), SphereType::compile);

    private SphereType() {
    }

    private static SphereKind compile(List<Sphere> spheres) {
        double[] data = new double[4 * spheres.size()];
        for (int i = 0; i < spheres.size(); i++) {
            Sphere s = spheres.get(i);
            int at = 4 * i; // centre, radius
            data[at] = s.center().x();
            data[at + 1] = s.center().y();
            data[at + 2] = s.center().z();
            data[at + 3] = s.radius();
        }
        return new SphereKind(data);
    }
}
