package glint.accel;

import glint.geometry.Primitives;
import glint.geometry.Hit;

/**
 * What every ray asks of the scene's geometry: its nearest hit, and how much light passes along
 * it up to a distance (a shadow ray). Rays are unit length, world space; {@code skip} is the
 * number of a primitive the ray leaves on its outer side (it cannot meet it there again), or
 * {@link Hit#NONE}; {@code inside} the closed primitive the ray has just entered or goes on
 * inside of (refracted into it, reflected inside it), or {@link Hit#NONE}: a hint an aggregate may
 * use ({@link EmptyInteriors}). The ray starts inside that primitive, or, where its origin's offset
 * off the surface is larger than the primitive, past it, moving away, so that it misses it.
 * Implementations ({@link Bvh}, the filter {@link EmptyInteriors}, and in the tests a flat list)
 * are immutable and shared by the render threads; each thread passes its own traversal {@code stack}, made by
 * {@link #newStack}. {@link AggregatePolicy} picks one for a scene.
 */
public interface Aggregate {

    /**
     * The nearest hit with t in (0, tMax) into {@code hit} (its t, primitive, kind and index; the
     * surface is left to {@link Primitives#describe}); false, leaving {@code hit} alone, if none.
     */
    boolean nearest(double ox, double oy, double oz, double dx, double dy, double dz, double tMax, int skip,
                    int inside, Hit hit, TraversalStack stack);

    /**
     * The fraction of light that passes along the ray from o before tMax: the product of
     * {@code pass[p]} over the primitives p it meets there (each counted once), so 1 when it meets
     * none; stops at the first that passes nothing. With every {@code pass} 0 this is the
     * any-hit query of a shadow ray.
     */
    double transmittance(double ox, double oy, double oz, double dx, double dy, double dz, double tMax, int skip,
                         double[] pass, TraversalStack stack);

    /**
     * Gathers into {@code out} the primitives a ray inside the frustum may meet: every unbounded
     * one, and every bounded one whose box may reach into the frustum.
     */
    void gather(Frustum frustum, Candidates out, TraversalStack stack);

    /**
     * Whether closed primitive p has an inside nothing else reaches into, so that a ray inside it
     * meets only p's far side (found once, when the aggregate is built); false where the
     * aggregate does not know.
     */
    default boolean emptyInside(int p) {
        return false;
    }

    /** The primitives it searches. */
    Primitives primitives();

    /** A traversal stack for one thread's queries, sized for this aggregate. */
    TraversalStack newStack();
}
