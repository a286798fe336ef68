package glint.geometry;

/**
 * The one place that decides how a scene's rays search its primitives, and every threshold of
 * that decision. Each was measured on scenes/bench (800x600, 1 spp, depth 5, cook-torrance; two
 * builds run side by side, one thread each, render CPU a frame, medians of 30-40 frames,
 * 2026-12-02; docs/benchmarks.md).
 */
public final class AggregatePolicy {

    /**
     * Primitives a {@link Bvh} leaf holds at most. Leaves of 1, 2, 4 and 8 gave the same render
     * CPU on glass-25 and field-1000 to within the measurement's 5 % spread; 4 builds the fewest
     * nodes of those.
     */
    public static final int LEAF_SIZE = 4;

    /**
     * A row of camera rays searches only the primitives its frustum may hold when they are at
     * most this many; otherwise each of its rays searches the aggregate. Gathering per row took
     * 6-16 % off a frame of the default scene, glass-25 and field-1000.
     */
    public static final int MOST_ROW_CANDIDATES = 16;

    /**
     * Rays leaving a closed primitive use its direction cells ({@link LeavingCells}) in scenes of
     * at most this many primitives: their build grows with the square at worst (field-1000: 0.19 s
     * of compile against 4 ms without; scenes/field.yaml's 3560 would take 0.7 s). Measured on
     * default, glass-25 and field-1000 with CompareBuilds (2 threads, 3 runs of 10 pairs):
     * B/A 0.92-1.01, 0.78-0.85 and 0.90-0.97.
     */
    public static final int MOST_CELL_PRIMITIVES = 1024;

    private AggregatePolicy() {
    }

    /**
     * The aggregate for these primitives: a {@link Bvh} (against testing every primitive, it took
     * 7-12 % off a frame of 5 glass or matte spheres and 27-41 % off 10 to 25, and cost nothing on
     * the default scene's 3), behind the {@link EmptyInteriors} filter where a closed primitive
     * has an empty inside (13 % off glass-25, 2-3 % off the default scene and glass-5), and behind
     * it the {@link LeavingCells} filter for rays leaving a closed primitive's outer side (a ray
     * hinting {@code inside} is answered by the first filter, one with {@code skip} by the second).
     */
    public static Aggregate choose(Primitives primitives) {
        Bvh bvh = new Bvh(primitives, LEAF_SIZE);
        return EmptyInteriors.around(primitives.count() <= MOST_CELL_PRIMITIVES ? LeavingCells.around(bvh) : bvh);
    }
}
