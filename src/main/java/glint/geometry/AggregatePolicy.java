package glint.geometry;

/**
 * The one place that decides how a scene's rays search its primitives, and every threshold of
 * that decision.
 */
public final class AggregatePolicy {

    /**
     * Scenes with more bounded primitives than this get a {@link Bvh}; fewer are searched as a
     * {@link FlatList}. Measured on scenes/bench (800x600, 1 spp, depth 5, cook-torrance,
     * JMH, docs/benchmarks.md): see {@link #BVH_MIN_BOUNDED}'s note there.
     */
    public static final int BVH_MIN_BOUNDED = 8;

    /**
     * A row of camera rays searches only the primitives its frustum may hold when they are at
     * most this many; otherwise it asks the aggregate.
     */
    public static final int MOST_ROW_CANDIDATES = 16;

    /** Primitives a {@link Bvh} leaf holds at most. */
    public static final int LEAF_SIZE = 4;

    private AggregatePolicy() {
    }

    /** The aggregate for these primitives. */
    public static Aggregate choose(Primitives primitives) {
        int bounded = 0;
        for (int p = 0; p < primitives.count(); p++) {
            bounded += primitives.bounded(p) ? 1 : 0;
        }
        Aggregate searched = bounded > BVH_MIN_BOUNDED ? new Bvh(primitives, LEAF_SIZE) : new FlatList(primitives);
        return EmptyInteriors.around(searched);
    }
}
