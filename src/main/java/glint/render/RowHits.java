package glint.render;

/**
 * What the camera rays of one tile row met, per worker, kept between the stages a row is traced in:
 * first every ray's nearest hit, then every hit's surface, then the shading, with the matte hits
 * lit together light by light. Working a stage across the row keeps each loop short and its
 * iterations independent, so the square roots and divisions of neighbouring rays overlap instead
 * of waiting on one another. Slot i belongs to camera ray i of the row ({@link CameraRows}); the
 * matte arrays are indexed by the matte hit's place in {@link #matteRays}. World space throughout.
 * The arrays grow, never shrink.
 */
final class RowHits {

    // stage 1: the surface met (the other is -1; both -1 for a miss) and the distance to it
    int[] sphere = new int[0], plane = new int[0];
    double[] t = new double[0];

    // stage 2: hit point on the surface, unit normal facing the ray, cosine of incidence (>= 0),
    // offset of rays leaving the hit, whether the ray met the front side, the material
    double[] px = new double[0], py = new double[0], pz = new double[0];
    double[] nx = new double[0], ny = new double[0], nz = new double[0];
    double[] cosIncident = new double[0], offset = new double[0];
    boolean[] entering = new boolean[0];
    int[] material = new int[0];

    // stage 3: the rays that met a matte surface, in row order
    int[] matteRays = new int[0];
    int matteCount;

    // stage 4, per matte hit: the current light's sample (unit direction, distance, n.l and the
    // irradiance it brings, n.l included) and the radiance summed over the lights so far
    double[] toLightX = new double[0], toLightY = new double[0], toLightZ = new double[0];
    double[] lightDistance = new double[0], cosLight = new double[0];
    double[] lightR = new double[0], lightG = new double[0], lightB = new double[0];
    double[] sumR = new double[0], sumG = new double[0], sumB = new double[0];

    /** Makes room for a row of {@code rays} camera rays. */
    void fit(int rays) {
        if (sphere.length >= rays) {
            return;
        }
        sphere = new int[rays];
        plane = new int[rays];
        t = new double[rays];
        px = new double[rays];
        py = new double[rays];
        pz = new double[rays];
        nx = new double[rays];
        ny = new double[rays];
        nz = new double[rays];
        cosIncident = new double[rays];
        offset = new double[rays];
        entering = new boolean[rays];
        material = new int[rays];
        matteRays = new int[rays];
        toLightX = new double[rays];
        toLightY = new double[rays];
        toLightZ = new double[rays];
        lightDistance = new double[rays];
        cosLight = new double[rays];
        lightR = new double[rays];
        lightG = new double[rays];
        lightB = new double[rays];
        sumR = new double[rays];
        sumG = new double[rays];
        sumB = new double[rays];
    }

    /** Stores the caster's last nearest-hit answer as ray i's hit. */
    void storeHit(int ray, RayCaster hit, boolean found) {
        sphere[ray] = found ? hit.hitSphere : -1;
        plane[ray] = found ? hit.hitPlane : -1;
        t[ray] = hit.hitT;
    }

    boolean met(int ray) {
        return sphere[ray] >= 0 || plane[ray] >= 0;
    }

    /** The skip code of rays leaving ray i's hit on the side the ray came from. */
    int skipNear(int ray) {
        return RayCaster.skipNear(sphere[ray], plane[ray], entering[ray]);
    }

    /** The skip code of rays passing through ray i's hit to the surface's other side. */
    int skipFar(int ray) {
        return RayCaster.skipFar(sphere[ray], plane[ray], entering[ray]);
    }
}
