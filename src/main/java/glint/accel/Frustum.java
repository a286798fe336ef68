package glint.accel;

/**
 * Scratch value: the rays from one point (the apex) whose directions lie between four edge
 * directions, such as the camera rays of a row of pixels: four planes through the apex, each
 * normal pointing inwards (world space).
 */
public final class Frustum {

    double apexX, apexY, apexZ;
    /** Inward normals of the four side planes, 3 doubles each. */
    final double[] normals = new double[12];

    /**
     * Sets the frustum from its apex and its four edge directions, given in order around it
     * (each next to the one before and the one after; the fourth next to the first).
     */
    public void set(double ax, double ay, double az, double[] edges) {
        apexX = ax;
        apexY = ay;
        apexZ = az;
        double cx = 0, cy = 0, cz = 0; // a direction inside: the edges' sum
        for (int e = 0; e < 4; e++) {
            cx += edges[3 * e];
            cy += edges[3 * e + 1];
            cz += edges[3 * e + 2];
        }
        for (int e = 0; e < 4; e++) {
            int a = 3 * e, b = 3 * ((e + 1) % 4);
            double nx = edges[a + 1] * edges[b + 2] - edges[a + 2] * edges[b + 1];
            double ny = edges[a + 2] * edges[b] - edges[a] * edges[b + 2];
            double nz = edges[a] * edges[b + 1] - edges[a + 1] * edges[b];
            double sign = nx * cx + ny * cy + nz * cz >= 0 ? 1 : -1;
            normals[a] = sign * nx;
            normals[a + 1] = sign * ny;
            normals[a + 2] = sign * nz;
        }
    }

    /**
     * Whether the box (min x, y, z, max x, y, z from {@code at}) may reach into the frustum:
     * false only when it lies wholly outside one of the side planes.
     */
    boolean mayHold(double[] box, int at) {
        for (int e = 0; e < 4; e++) {
            double nx = normals[3 * e], ny = normals[3 * e + 1], nz = normals[3 * e + 2];
            // the box corner farthest along the normal
            double px = (nx >= 0 ? box[at + 3] : box[at]) - apexX;
            double py = (ny >= 0 ? box[at + 4] : box[at + 1]) - apexY;
            double pz = (nz >= 0 ? box[at + 5] : box[at + 2]) - apexZ;
            if (nx * px + ny * py + nz * pz < 0) {
                return false;
            }
        }
        return true;
    }
}
