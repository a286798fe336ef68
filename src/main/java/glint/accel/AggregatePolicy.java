package glint.accel;

import glint.geometry.Primitives;

/**
 * The one place that decides how a scene's rays search its primitives, and every threshold and
 * margin of the structures that search them. Each says what it was measured on, or that it was
 * chosen and not measured. The measured ones were measured on scenes/bench (800x600, 1 spp, depth
 * 5, cook-torrance, render CPU a frame, 2026-12-02; docs/records/benchmarks.md): the first ones with two
 * builds run side by side, one thread each, medians of 30-40 frames; the cells with
 * {@code CompareBuilds}.
 */
public final class AggregatePolicy {

    /**
     * Primitives a {@link Bvh} leaf holds at most. Leaves of 1, 2, 4 and 8 gave the same render
     * CPU on glass-25 and field-1000 to within the measurement's 5 % spread; 4 builds the fewest
     * nodes of those.
     */
    public static final int LEAF_SIZE = 4;

    /**
     * A row of camera rays searches only the primitives its frustum may hold, primitive by
     * primitive, when they are at most this many; otherwise each of its rays searches the aggregate.
     * Gathering per row took 6-16 % off a frame of the default scene, glass-25 and field-1000. With
     * CompareBuilds (2 threads, 10 pairs a run), 64 against 16 took 0.86-0.91 of field-1000's
     * render CPU a frame (2 runs) and left glass-25 and the default scene alike (0.99-1.04); 128
     * gave the same as 64, 256 a little more (1.04).
     */
    public static final int MOST_ROW_CANDIDATES = 64;

    /**
     * Rays leaving a closed primitive use its direction cells ({@link LeavingCells}) in scenes of
     * at most this many primitives. Measured with CompareBuilds (2 threads, 10 pairs a run, 6 runs):
     * glass-25 (26 primitives) took 0.76-0.85 of the render CPU a frame, the default scene 0.87-1.01;
     * on field-1000 (1,001) the ratio wandered from 0.90 to 1.02 while the cells took 0.19 s of
     * compile (4 ms without) and 4.5 MB, their build growing with the square of the count at worst.
     * Up to 256 the build stays under 30 ms (the first 254 spheres of field-1000: 26 ms).
     */
    public static final int MOST_CELL_PRIMITIVES = 256;

    /**
     * Cells along a cube face's side around a point light ({@link LightCells}). With CompareBuilds
     * (2 threads, 10 pairs a run, 3 runs each, a cap of 16, every scene given cells) 8 took 0.95-1.00
     * of the default scene's render CPU a frame, 0.92-1.01 of glass-25's and 0.95-1.02 of
     * field-1000's; 16 took 0.96-0.97, 0.90-0.93 and 0.88-0.93; 32 took 0.93-0.96, 0.78-0.94 and
     * 0.75-0.80.
     */
    public static final int LIGHT_CELLS = 32;
    /**
     * The most primitives a light's cell lists; a cell that would list more searches. With 32 cells
     * a side, a cap of 8 took 0.90-0.97 of the default scene, 0.87-0.98 of glass-25 and 0.86-0.88 of
     * field-1000; 16 took 0.93-0.96, 0.78-0.94 and 0.75-0.80; 32 took 0.87-0.95, 0.85-0.91 and
     * 0.75-0.84, and leaves none of field-1000's 6,144 cells falling back (16: 43).
     */
    public static final int LIGHT_CELL_CAP = 32;
    /**
     * Shadow rays towards a point light use its direction cells in scenes of at most this many
     * primitives. A light's cells take 10 ms to work out among 1,000 spheres on a floor, 26 ms among
     * 4,000 and 78 ms among 16,000 (32 cells a side, a cap of 32, a warm JVM).
     */
    public static final int MOST_LIGHT_CELL_PRIMITIVES = 4096;
    /** Only the first this many point lights of a scene get cells: each takes up to 0.8 MB and its build time. */
    public static final int MOST_CELL_LIGHTS = 8;

    /**
     * Bins along a node's widest centroid axis among whose edges a {@link Bvh} node's split is chosen by
     * the surface-area heuristic ({@link BvhBuilder}). Chosen; against 6 and 24 bins, two
     * CompareBuilds runs (1 thread, 8 and 12 pairs, 2026-12-02, a loaded shared machine) gave 6
     * 1.00 and 1.05 of the default scene's render CPU a frame, 0.95 and 0.96 of glass-25's, 0.98 and
     * 0.97 of field-1000's; 24 gave 0.95 and 1.06, 0.80 and 0.93, 0.99 and 0.98: within the runs'
     * spread (their quartiles 0.79-1.25), no steady difference.
     */
    static final int BVH_BINS = 12;

    /**
     * Primitives a leaf holds at most in the tree {@link CellMaps} walks to fill a cube map's cells.
     * It changes only how fast the cells are worked out, not what they list (each list is sorted).
     * Chosen equal to {@link #LEAF_SIZE}, not measured.
     */
    static final int CELL_TREE_LEAF_SIZE = 4;

    /**
     * Cells along a cube face's side around a closed primitive ({@link LeavingCells}): 6 x 8 x 8
     * direction cells a primitive (the cells as a whole were measured: see
     * {@link #MOST_CELL_PRIMITIVES}). Chosen; against 4 and 16, two CompareBuilds runs (1 thread, 8
     * and 12 pairs, 2026-12-02, a loaded shared machine) gave 4 1.02 and 1.06 of the default scene's
     * render CPU a frame and 0.96 and 1.02 of glass-25's, 16 1.11 and 1.07, 1.01 and 1.04; on
     * field-1000, which has no such cells, the same builds gave 0.94-1.10: no steady difference but
     * a hint that 16 is slower.
     */
    static final int LEAVING_CELLS = 8;

    /**
     * The most primitives a cell around a closed primitive lists ({@link LeavingCells}); a cell that
     * would list more searches. Chosen; against 8 and 32, the two runs of {@link #LEAVING_CELLS} gave
     * 8 0.98 and 1.13 of the default scene and 0.97 and 0.90 of glass-25, 32 1.03 and 1.10, 1.01 and
     * 1.00: within the runs' spread, no steady difference.
     */
    static final int LEAVING_CELL_CAP = 16;

    /**
     * A margin for the spawn offset, relative to max(1, distance from the scene's origin): how far
     * off the ball a cube map was worked out for a ray may start (end, for a shadow ray) and still
     * be answered from its cells. {@link LeavingCells} widens each closed primitive's bounding ball
     * by it (relative to max(1, |centre| + radius)); {@link LightCells} takes it as the radius of the
     * ball around the light (relative to max(1, |light|)). A spawned ray starts epsilon x max(1, |p|)
     * off the surface (epsilon 1e-9 by default, a thousandth of this margin), so with the default
     * epsilon every spawned ray is within it; a ray farther off is searched as usual (checked per
     * ray), so the margin decides only which rays use the cells. Chosen, not measured.
     */
    static final double SPAWN_MARGIN = 1e-6;

    /**
     * Angle (radians) every direction cell's cone is widened by when the cells' lists are worked out
     * ({@link CellCones}): a margin over the sampled cone's half-angle that also covers the rounding
     * of a ray's cell lookup and of the tests. A wider one lists more primitives a cell. Chosen, not
     * measured.
     */
    static final double CELL_CONE_SLACK = 1e-3;

    /**
     * Plane-primitive pairs up to which {@link EmptyInteriors} asks each plane of each primitive still
     * empty; above it, of nested groups of them first. The groups took 50,000 planes under 50,000
     * spheres from 36 s to seconds (commit ea91ef3); the threshold itself was chosen, not measured.
     */
    static final long EMPTY_PLANE_PAIRS_ONE_BY_ONE = 1 << 16;

    /** Primitives a leaf group of {@link EmptyInteriors}' nested groups holds at most. Chosen, not measured. */
    static final int EMPTY_GROUP_LEAF = 8;

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

    /**
     * The aggregate for shadow rays towards the point light at (x, y, z), the scene's
     * {@code ordinal}th point light (from 0), in a scene whose rays search {@code scene}: the
     * {@link LightCells} filter in front of it, or {@code scene} itself.
     */
    public static Aggregate forPointLight(Aggregate scene, int ordinal, double x, double y, double z) {
        return ordinal < MOST_CELL_LIGHTS && scene.primitives().count() <= MOST_LIGHT_CELL_PRIMITIVES
                ? LightCells.around(scene, x, y, z, LIGHT_CELLS, LIGHT_CELL_CAP) : scene;
    }
}
