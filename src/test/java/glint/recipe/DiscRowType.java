package glint.recipe;

import glint.geometry.DiscKind;
import glint.input.InputException;
import glint.math.Vector3d;
import glint.registry.Fields;
import glint.registry.ShapeType;
import java.util.List;

/**
 * The registration of the row of discs: {@code {type: disc_row, first: [x, y, z], step: [x, y, z],
 * count: n, radius: r}}, a {@link DiscRow} of n primitives, all of them compiled to one {@link DiscKind}.
 */
final class DiscRowType {

    static final ShapeType<DiscRow> TYPE = new ShapeType<>("disc_row", DiscRow.class,
            List.of("first", "step", "count", "radius"), DiscRowType::read, DiscRowType::compile, DiscRow::count);

    private DiscRowType() {
    }

    private static DiscRow read(Fields fields) throws InputException {
        double count = fields.number("count");
        if (!(count >= 1 && count <= 100 && count == Math.rint(count))) {
            throw fields.error("count", "count must be a whole number from 1 to 100, got " + count);
        }
        return new DiscRow(fields.vector("first"), fields.vector("step"), (int) count, fields.length("radius"));
    }

    private static DiscKind compile(List<DiscRow> rows) {
        int discs = rows.stream().mapToInt(DiscRow::count).sum();
        double[] data = new double[7 * discs];
        int at = 0;
        for (DiscRow row : rows) {
            for (int i = 0; i < row.count(); i++, at += 7) {
                Vector3d centre = row.first().add(row.step().scale(i));
                double[] values = {centre.x(), centre.y(), centre.z(), 0, 0, -1, row.radius()};
                System.arraycopy(values, 0, data, at, 7);
            }
        }
        return new DiscKind(data);
    }
}
