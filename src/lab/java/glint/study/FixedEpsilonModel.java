package glint.study;

/**
 * The textbook way to leave a surface, modelled outside the renderer: hit point p = o + t d (no
 * re-projection onto the surface) and a shadow ray from p + epsilon n with a fixed epsilon, in float
 * or double (every operation rounded to the precision). Intersections use the stable sphere form, so
 * that only the offset rule and the precision differ from Glint.
 */
public final class FixedEpsilonModel {

    private final Precision precision;
    private final double epsilon;

    public FixedEpsilonModel(Precision precision, double epsilon) {
        this.precision = precision;
        this.epsilon = epsilon;
    }

    /** Per pixel (rows top to bottom): true when the model finds the point lit by the light. */
    public boolean[] lit(ShadowScene scene) {
        boolean[] lit = new boolean[scene.width() * scene.height()];
        double ex = r(scene.eye().x()), ey = r(scene.eye().y()), ez = r(scene.eye().z());
        for (int y = 0; y < scene.height(); y++) {
            for (int x = 0; x < scene.width(); x++) {
                double[] d = scene.direction(x, y);
                lit[y * scene.width() + x] = shade(scene, ex, ey, ez, r(d[0]), r(d[1]), r(d[2]));
            }
        }
        return lit;
    }

    private boolean shade(ShadowScene scene, double ox, double oy, double oz, double dx, double dy, double dz) {
        double best = Double.POSITIVE_INFINITY;
        double[] hitSphere = null;
        for (double[] s : scene.spheres()) {
            double t = sphere(s, ox, oy, oz, dx, dy, dz);
            if (t < best) {
                best = t;
                hitSphere = s;
            }
        }
        double floorY = r(scene.floorY());
        if (scene.hasFloor()) {
            double t = floor(floorY, oy, dy);
            if (t < best) {
                best = t;
                hitSphere = null;
            }
        }
        if (best == Double.POSITIVE_INFINITY) {
            return false;
        }
        double px = r(ox + r(best * dx)), py = r(oy + r(best * dy)), pz = r(oz + r(best * dz));
        double nx = 0, ny = 1, nz = 0;
        if (hitSphere != null) {
            double radius = r(hitSphere[3]);
            nx = r(r(px - r(hitSphere[0])) / radius);
            ny = r(r(py - r(hitSphere[1])) / radius);
            nz = r(r(pz - r(hitSphere[2])) / radius);
        }
        if (r(r(r(nx * dx) + r(ny * dy)) + r(nz * dz)) > 0) { // seen from behind: face the viewer
            nx = -nx;
            ny = -ny;
            nz = -nz;
        }
        double sx = r(px + r(epsilon * nx)), sy = r(py + r(epsilon * ny)), sz = r(pz + r(epsilon * nz));
        double lx = r(r(scene.light().x()) - sx), ly = r(r(scene.light().y()) - sy), lz = r(r(scene.light().z()) - sz);
        double distance = r(Math.sqrt(r(r(r(lx * lx) + r(ly * ly)) + r(lz * lz))));
        lx = r(lx / distance);
        ly = r(ly / distance);
        lz = r(lz / distance);
        if (r(r(r(nx * lx) + r(ny * ly)) + r(nz * lz)) <= 0) {
            return false;
        }
        for (double[] s : scene.spheres()) {
            if (sphere(s, sx, sy, sz, lx, ly, lz) < distance) {
                return false;
            }
        }
        return !(scene.hasFloor() && floor(floorY, sy, ly) < distance);
    }

    private double sphere(double[] s, double ox, double oy, double oz, double dx, double dy, double dz) {
        if (precision == Precision.FLOAT) {
            float t = FloatSphere.stable((float) s[0], (float) s[1], (float) s[2], (float) s[3],
                    (float) ox, (float) oy, (float) oz, (float) dx, (float) dy, (float) dz);
            return t;
        }
        return glint.geometry.Intersect.sphereBefore(s[0], s[1], s[2], s[3], ox, oy, oz, dx, dy, dz,
                glint.geometry.Intersect.MISS);
    }

    /** The plane y = floorY: t = (floorY - oy) / dy, or a miss. */
    private double floor(double floorY, double oy, double dy) {
        if (dy == 0) {
            return Double.POSITIVE_INFINITY;
        }
        double t = r(r(floorY - oy) / dy);
        return t > 0 ? t : Double.POSITIVE_INFINITY;
    }

    private double r(double v) {
        return precision.round(v);
    }
}
