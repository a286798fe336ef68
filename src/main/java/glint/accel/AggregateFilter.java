package glint.accel;

import glint.geometry.Primitives;

/**
 * An aggregate in front of another that answers some queries itself (nearest hits for
 * {@link EmptyInteriors} and {@link LeavingCells}, shadow rays for {@link LightCells}) and hands
 * every other question to the one it filters.
 */
abstract class AggregateFilter implements Aggregate {

    /** The aggregate behind this filter. */
    final Aggregate searched;
    final Primitives primitives;

    AggregateFilter(Aggregate searched) {
        this.searched = searched;
        this.primitives = searched.primitives();
    }

    @Override
    public double transmittance(double ox, double oy, double oz, double dx, double dy, double dz, double tMax,
                                int skip, double[] pass, TraversalStack stack) {
        return searched.transmittance(ox, oy, oz, dx, dy, dz, tMax, skip, pass, stack);
    }

    @Override
    public void gather(Frustum frustum, Candidates out, TraversalStack stack) {
        searched.gather(frustum, out, stack);
    }

    @Override
    public boolean emptyInside(int p) {
        return searched.emptyInside(p);
    }

    @Override
    public Primitives primitives() {
        return primitives;
    }

    @Override
    public TraversalStack newStack() {
        return searched.newStack();
    }
}
