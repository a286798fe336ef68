package glint.render;

/**
 * The spheres that can shadow a point light, for a scene of few spheres: each sphere's cone of
 * directions seen from the light, widened as {@link LightBuffer}'s are. A shadow ray tests a
 * sphere only when the direction from the light to its surface point falls in that sphere's cone:
 * a dot product and a comparison, where finding the light buffer's cell costs a division, a face
 * chosen by branches and two conversions to integers. Built with the compiled scene; immutable.
 *
 * <p>The margin argument is the light buffer's: seen from the light, a shadow ray's points lie off
 * its direction by at most the cones' widening while the ray's origin is no further than {@link
 * #maxOffset} from the surface; rays offset further take the full test.
 */
final class LightCones {

    /**
     * Scenes of at most this many spheres get cones; more get a {@link LightBuffer}. Millions of
     * instructions a frame of the render thread (800x600, 1 sample, depth 5), with cones and with
     * the buffer: default scene (3 spheres) 321-322 and 324-332, 5 glass spheres 279-284 and 265-266,
     * 5 matte 181-182 and 175-179 (docs/benchmarks.md).
     */
    static final int MOST_SPHERES = 4;

    /**
     * Taken off each cone's cosine, so that rounding in the cosine and in the dot product can
     * only widen a cone: about 4.5e-5 radians at a cone's axis, far less off it.
     */
    private static final double COSINE_SLACK = 1e-9;

    /** Shadow rays whose origin lies further than this from the surface point must take the full test. */
    final double maxOffset;
    /**
     * Per sphere, in the scene's order: the unit axis of its cone (from the light towards the
     * centre) and the cosine of its widened half-angle, 4 doubles; the cosine is -2 where the cone
     * holds every direction.
     */
    final double[] cones;
    final int count;

    private LightCones(double maxOffset, double[] cones, int count) {
        this.maxOffset = maxOffset;
        this.cones = cones;
        this.count = count;
    }

    /** The cones of {@code count} spheres (cx, cy, cz, r each) seen from the point light at (x, y, z). */
    static LightCones build(double[] spheres, int count, double x, double y, double z) {
        double[] cones = new double[4 * count];
        double nearest = Double.POSITIVE_INFINITY;
        for (int i = 0; i < count; i++) {
            int k = 4 * i;
            double cx = spheres[k] - x, cy = spheres[k + 1] - y, cz = spheres[k + 2] - z, radius = spheres[k + 3];
            double distance = Math.sqrt(cx * cx + cy * cy + cz * cz);
            // sin(half-angle) = r / d + margin, as ConeCells widens: at least asin(r / d) + margin
            double widened = radius + ConeCells.ANGLE_MARGIN * distance;
            if (!(distance > widened * (1 + 1e-9))) {
                cones[k + 3] = -2; // the light is inside the sphere or nearly touching it
                continue;
            }
            double sine = widened / distance;
            cones[k] = cx / distance;
            cones[k + 1] = cy / distance;
            cones[k + 2] = cz / distance;
            cones[k + 3] = Math.sqrt(1 - sine * sine) - COSINE_SLACK;
            nearest = Math.min(nearest, distance - radius);
        }
        return new LightCones(Math.sin(ConeCells.ANGLE_MARGIN) * nearest, cones, count);
    }

    /** Whether sphere i's cone holds the direction from the light opposite to unit (dx, dy, dz). */
    boolean holds(int i, double dx, double dy, double dz) {
        int k = 4 * i;
        return -(dx * cones[k] + dy * cones[k + 1] + dz * cones[k + 2]) >= cones[k + 3];
    }
}
