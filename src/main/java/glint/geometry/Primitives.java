package glint.geometry;

import java.util.List;
import java.util.stream.IntStream;

/**
 * A scene's primitives: its shape kinds, and one number per primitive across them (kind 0's
 * primitives first, then kind 1's, ...). A hit names a primitive by that number and, plainly, by
 * its kind and its index within the kind.
 */
public final class Primitives {

    private final PrimitiveKind[] kinds;
    private final int[] kindOf;
    private final int[] indexOf;
    private final int count;

    public Primitives(List<PrimitiveKind> kinds) {
        this.kinds = kinds.toArray(new PrimitiveKind[0]);
        int total = 0;
        for (PrimitiveKind kind : this.kinds) {
            total += kind.count();
        }
        this.count = total;
        this.kindOf = new int[total];
        this.indexOf = new int[total];
        for (int k = 0, p = 0; k < this.kinds.length; k++) {
            for (int i = 0; i < this.kinds[k].count(); i++, p++) {
                kindOf[p] = k;
                indexOf[p] = i;
            }
        }
    }

    /** How many primitives, of every kind. */
    public int count() {
        return count;
    }

    public int kindCount() {
        return kinds.length;
    }

    public PrimitiveKind kind(int k) {
        return kinds[k];
    }

    /** The kinds, in numbering order. */
    public List<PrimitiveKind> kinds() {
        return List.of(kinds);
    }

    public int kindOf(int primitive) {
        return kindOf[primitive];
    }

    public int indexOf(int primitive) {
        return indexOf[primitive];
    }

    /**
     * The kind of each primitive of a list of numbers: a structure that keeps it beside the list
     * calls the kind straight away, rather than looking it up per test.
     */
    public PrimitiveKind[] kindsOf(int[] numbers) {
        PrimitiveKind[] out = new PrimitiveKind[numbers.length];
        for (int i = 0; i < numbers.length; i++) {
            out[i] = kinds[kindOf[numbers[i]]];
        }
        return out;
    }

    /** The index within its kind of each primitive of a list of numbers. */
    public int[] indicesOf(int[] numbers) {
        int[] out = new int[numbers.length];
        for (int i = 0; i < numbers.length; i++) {
            out[i] = indexOf[numbers[i]];
        }
        return out;
    }

    /** The numbers of the unbounded primitives (planes), in order: every ray tests them. */
    public int[] unbounded() {
        return IntStream.range(0, count).filter(q -> !bounded(q)).toArray();
    }

    public boolean bounded(int primitive) {
        return kinds[kindOf[primitive]].bounded(indexOf[primitive]);
    }

    public void bounds(int primitive, double[] box, int at) {
        kinds[kindOf[primitive]].bounds(indexOf[primitive], box, at);
    }

    /** {@link PrimitiveKind#intersect} of a primitive given by its number. */
    public double intersect(int primitive, double ox, double oy, double oz, double dx, double dy, double dz,
                            double tMax) {
        return kinds[kindOf[primitive]].intersect(indexOf[primitive], ox, oy, oz, dx, dy, dz, tMax);
    }

    /** {@link PrimitiveKind#nearestFromOrigin} of a primitive given by its number. */
    public void nearestFromOrigin(int primitive, double ox, double oy, double oz, double[] dx, double[] dy,
                                  double[] dz, int first, int end, double[] nearestT, int[] nearestPrimitive) {
        kinds[kindOf[primitive]].nearestFromOrigin(indexOf[primitive], primitive, ox, oy, oz, dx, dy, dz, first, end,
                nearestT, nearestPrimitive);
    }

    /** Whether a ray leaving the primitive into its inside can meet it again ({@link PrimitiveKind#closed}). */
    public boolean closed(int primitive) {
        return kinds[kindOf[primitive]].closed();
    }

    /**
     * Records a hit of primitive {@code primitive} at distance t in {@code hit}: its number, kind
     * and index. The surface is filled in later, by {@link #describe}, for the hit that is kept.
     */
    public void record(Hit hit, int primitive, double t) {
        hit.t = t;
        hit.primitive = primitive;
        hit.kind = kindOf[primitive];
        hit.index = indexOf[primitive];
    }

    /**
     * Fills the surface of the hit the unit ray from o along d found: the point moved onto the
     * surface and the outward normal.
     */
    public void describe(Hit hit, double ox, double oy, double oz, double dx, double dy, double dz) {
        double t = hit.t;
        kinds[hit.kind].surfaceAt(hit.index, ox + t * dx, oy + t * dy, oz + t * dz, hit);
    }
}
