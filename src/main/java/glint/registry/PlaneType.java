package glint.registry;

import glint.geometry.PlaneKind;
import glint.scene.Plane;
import java.util.List;

/** {@code {type: plane, point: [x, y, z], normal: [x, y, z]}}: a {@link Plane}, compiled to a {@link PlaneKind}. */
public final class PlaneType {

    public static final ShapeType<Plane> TYPE = new ShapeType<>("plane", Plane.class, List.of("point", "normal"),
            fields -> new Plane(fields.vector("point"), fields.direction("normal")), PlaneType::compile);

    private PlaneType() {
    }

    private static PlaneKind compile(List<Plane> planes) {
        double[] data = new double[4 * planes.size()];
        for (int i = 0; i < planes.size(); i++) {
            Plane p = planes.get(i);
            int at = 4 * i; // unit normal, normal . point
            data[at] = p.normal().x();
            data[at + 1] = p.normal().y();
            data[at + 2] = p.normal().z();
            data[at + 3] = p.normal().dot(p.point());
        }
        return new PlaneKind(data);
    }
}
