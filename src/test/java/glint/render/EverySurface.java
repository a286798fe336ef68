package glint.render;

/** Test helper: the nearest hit found by testing every sphere and plane of a compiled scene. */
final class EverySurface {

    private EverySurface() {
    }

    /** A nearest hit: its distance ({@link Intersect#MISS} for none) and the sphere or plane met, else -1. */
    record Hit(double t, int sphere, int plane) {
    }

    /** The nearest hit along the ray, leaving out skippedSphere and skippedPlane (-1: none). */
    static Hit nearest(RenderScene s, double ox, double oy, double oz, double dx, double dy, double dz,
                       int skippedSphere, int skippedPlane) {
        double nearest = Intersect.MISS;
        int sphere = -1, plane = -1;
        for (int i = 0; i < s.sphereCount; i++) {
            int k = 4 * i;
            double t = Intersect.sphere(s.spheres[k], s.spheres[k + 1], s.spheres[k + 2], s.spheres[k + 3],
                    ox, oy, oz, dx, dy, dz);
            if (i != skippedSphere && t < nearest) {
                nearest = t;
                sphere = i;
            }
        }
        for (int i = 0; i < s.planeCount; i++) {
            int k = 4 * i;
            double t = Intersect.plane(s.planes[k], s.planes[k + 1], s.planes[k + 2], s.planes[k + 3],
                    ox, oy, oz, dx, dy, dz);
            if (i != skippedPlane && t < nearest) {
                nearest = t;
                plane = i;
                sphere = -1;
            }
        }
        return new Hit(nearest, sphere, plane);
    }
}
