package glint.recipe;

import glint.geometry.DiscKind;
import glint.math.Vector3d;
import glint.scene.Shape;
import glint.scene.ShapeType;
import java.util.List;

/**
 * A primitive kind added by the recipe of docs/architecture.md, in test sources only: a flat disc,
 * written {@code {type: disc, center: [x, y, z], normal: [x, y, z], radius: r}}.
 */
public record Disc(Vector3d center, Vector3d normal, double radius) implements Shape {

    public static final ShapeType<Disc> TYPE = new ShapeType<>("disc", Disc.class, List.of("center", "normal", "radius"),
            fields -> new Disc(fields.vector("center"), fields.direction("normal"), fields.length("radius")),
            Disc::compile);

    private static DiscKind compile(List<Disc> discs) {
        double[] data = new double[7 * discs.size()];
        for (int i = 0; i < discs.size(); i++) {
            Disc d = discs.get(i);
            double[] values = {d.center.x(), d.center.y(), d.center.z(), d.normal.x(), d.normal.y(), d.normal.z(),
                d.radius};
            System.arraycopy(values, 0, data, 7 * i, 7);
        }
        return new DiscKind(data);
    }
}
