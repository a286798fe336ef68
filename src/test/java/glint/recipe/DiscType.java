package glint.recipe;

import glint.geometry.DiscKind;
import glint.registry.ShapeType;
import java.util.List;

/**
 * The registration of the disc: {@code {type: disc, center: [x, y, z], normal: [x, y, z], radius: r}},
 * a {@link Disc}, compiled to a {@link DiscKind}.
 */
public final class DiscType {

    public static final ShapeType<Disc> TYPE = new ShapeType<>("disc", Disc.class, List.of("center", "normal", "radius"),
            fields -> new Disc(fields.vector("center"), fields.direction("normal"), fields.length("radius")),
            DiscType::compile);

    private DiscType() {
    }

    private static DiscKind compile(List<Disc> discs) {
        double[] data = new double[7 * discs.size()];
        for (int i = 0; i < discs.size(); i++) {
            Disc d = discs.get(i);
            double[] values = {d.center().x(), d.center().y(), d.center().z(), d.normal().x(), d.normal().y(),
                d.normal().z(), d.radius()};
            System.arraycopy(values, 0, data, 7 * i, 7);
        }
        return new DiscKind(data);
    }
}
