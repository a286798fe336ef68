package glint.accel;

import glint.geometry.Hit;
import glint.geometry.PrimitiveKind;
import glint.geometry.Primitives;

/**
 * Primitives in slots, each slot keeping the primitive's number, its kind and its index within the
 * kind, so that a test calls its kind straight away: a {@link Bvh}'s leaves, and the unbounded
 * primitives every ray tests (in the hierarchy and in a {@link CellFilter}). A query tests a run of
 * slots [from, end) in their order.
 */
final class PrimitiveSlots {

    private final Primitives primitives;
    private final int[] number;
    private final PrimitiveKind[] kind;
    private final int[] index;

    PrimitiveSlots(Primitives primitives, int[] numbers) {
        this.primitives = primitives;
        this.number = numbers;
        this.kind = primitives.kindsOf(numbers);
        this.index = primitives.indicesOf(numbers);
    }

    /** How many slots. */
    int count() {
        return number.length;
    }

    /** The number of the primitive in a slot. */
    int number(int slot) {
        return number[slot];
    }

    /**
     * The nearest hit among the slots [from, end) but {@code skip} with t below {@code tMax}: its t,
     * recorded into {@code hit} (its t, primitive, kind and index); {@code tMax}, leaving {@code hit}
     * alone, if none. Where two are met at the same distance, the one in the earlier slot.
     */
    double nearest(int from, int end, double ox, double oy, double oz, double dx, double dy, double dz,
                   double tMax, int skip, Hit hit) {
        double nearest = tMax;
        int found = Hit.NONE;
        for (int slot = from; slot < end; slot++) {
            if (number[slot] != skip) {
                double t = kind[slot].intersect(index[slot], ox, oy, oz, dx, dy, dz, nearest);
                if (t < nearest) {
                    nearest = t;
                    found = number[slot];
                }
            }
        }
        if (found != Hit.NONE) {
            primitives.record(hit, found, nearest);
        }
        return nearest;
    }

    /**
     * {@code passed} times {@code pass[q]} of each primitive q but {@code skip} in the slots
     * [from, end) that the ray meets before tMax, multiplied in the slots' order; 0 as soon as one
     * passes nothing.
     */
    double transmittance(int from, int end, double ox, double oy, double oz, double dx, double dy, double dz,
                         double tMax, int skip, double[] pass, double passed) {
        for (int slot = from; slot < end; slot++) {
            int q = number[slot];
            if (q != skip && kind[slot].intersect(index[slot], ox, oy, oz, dx, dy, dz, tMax) < tMax) {
                passed *= pass[q];
                if (passed == 0) {
                    return 0;
                }
            }
        }
        return passed;
    }
}
