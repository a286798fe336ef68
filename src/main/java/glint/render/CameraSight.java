package glint.render;

/**
 * Scratch value: the camera seen from a world point (world space), as {@link CameraModel#sees} chose a
 * point of its lens: that point, the film point whose ray from it meets the world point, the unit
 * direction and distance from the world point to the lens point, and the camera's importance along
 * the ray ({@link CameraModel#directionPdf}).
 */
public final class CameraSight {

    /** The point of the lens (the eye, for a pinhole). */
    public double lensX, lensY, lensZ;
    /** The film point, in pixels from the image's top-left corner. */
    public double filmX, filmY;
    /** The unit direction from the world point towards the lens point, and the distance between them. */
    public double towardX, towardY, towardZ, distance;
    /** The camera's importance along the ray: the density per solid angle of a camera ray along it. */
    public double importance;

    /** Sets the lens point and, from world point p, the direction and distance to it. */
    void set(double px, double py, double pz, double lx, double ly, double lz) {
        lensX = lx;
        lensY = ly;
        lensZ = lz;
        double vx = lx - px, vy = ly - py, vz = lz - pz;
        distance = Math.sqrt(vx * vx + vy * vy + vz * vz);
        double inv = 1 / distance;
        towardX = vx * inv;
        towardY = vy * inv;
        towardZ = vz * inv;
    }
}
