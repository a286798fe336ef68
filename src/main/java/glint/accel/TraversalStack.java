package glint.accel;

/**
 * Scratch value of one thread's hierarchy traversals: the nodes waiting to be visited and the
 * distances at which the ray enters their boxes. Made by {@link Aggregate#newStack}, sized for
 * the aggregate's tree.
 */
public final class TraversalStack {

    final int[] nodes;
    final double[] entries;
    /** How many nodes wait, between the steps of one walk ({@link Bvh}). */
    int waiting;

    TraversalStack(int capacity) {
        nodes = new int[capacity];
        entries = new double[capacity];
    }
}
