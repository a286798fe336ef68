package glint.render;

/**
 * Finds the spheres nothing else reaches into: no other sphere overlaps them and no plane cuts
 * them. A ray inside such a sphere (refracted into glass, or reflected inside it) can only meet
 * that sphere, so it needs no search. Touching counts as not reaching in: the open ball lies
 * strictly on one side of a tangent plane or sphere, which a ray from inside can meet only where
 * it leaves the ball anyway.
 */
final class EmptySpheres {

    private EmptySpheres() {
    }

    /**
     * For each sphere (cx, cy, cz, r in {@code spheres}), whether it is empty. Planes are nx, ny, nz,
     * offset with a unit normal. Uses the hierarchy, when there is one, to find the candidates.
     */
    static boolean[] find(double[] spheres, int sphereCount, double[] planes, int planeCount, SphereBvh bvh) {
        boolean[] empty = new boolean[sphereCount];
        int[] stack = new int[128];
        for (int i = 0; i < sphereCount; i++) {
            empty[i] = !cutByAPlane(spheres, i, planes, planeCount)
                    && !(bvh == null ? overlapsAny(spheres, i, 0, sphereCount) : overlapsAny(spheres, i, bvh, stack));
        }
        return empty;
    }

    private static boolean cutByAPlane(double[] spheres, int i, double[] planes, int planeCount) {
        double cx = spheres[4 * i], cy = spheres[4 * i + 1], cz = spheres[4 * i + 2], r = spheres[4 * i + 3];
        for (int j = 0; j < planeCount; j++) {
            int k = 4 * j;
            double distance = planes[k] * cx + planes[k + 1] * cy + planes[k + 2] * cz - planes[k + 3];
            if (Math.abs(distance) < r) {
                return true;
            }
        }
        return false;
    }

    /** Whether sphere i overlaps any of spheres [first, end) other than itself. */
    private static boolean overlapsAny(double[] spheres, int i, int first, int end) {
        for (int j = first; j < end; j++) {
            if (j != i && overlap(spheres, i, j)) {
                return true;
            }
        }
        return false;
    }

    private static boolean overlapsAny(double[] spheres, int i, SphereBvh bvh, int[] stack) {
        double cx = spheres[4 * i], cy = spheres[4 * i + 1], cz = spheres[4 * i + 2], r = spheres[4 * i + 3];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            int node = stack[--top];
            int b = 6 * node;
            double[] box = bvh.bounds;
            if (box[b] >= cx + r || box[b + 3] <= cx - r || box[b + 1] >= cy + r || box[b + 4] <= cy - r
                    || box[b + 2] >= cz + r || box[b + 5] <= cz - r) {
                continue; // the boxes do not overlap, so neither do the spheres
            }
            int link = bvh.links[2 * node], count = bvh.links[2 * node + 1];
            if (count > 0) {
                if (overlapsAny(spheres, i, link, link + count)) {
                    return true;
                }
            } else {
                stack[top++] = link;
                stack[top++] = link + 1;
            }
        }
        return false;
    }

    /** Whether the open balls of spheres i and j share a point. */
    private static boolean overlap(double[] spheres, int i, int j) {
        double dx = spheres[4 * i] - spheres[4 * j];
        double dy = spheres[4 * i + 1] - spheres[4 * j + 1];
        double dz = spheres[4 * i + 2] - spheres[4 * j + 2];
        double reach = spheres[4 * i + 3] + spheres[4 * j + 3];
        return dx * dx + dy * dy + dz * dz < reach * reach;
    }
}
