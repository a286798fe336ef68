package glint.render;

import glint.geometry.Primitives;
import glint.shading.Lights;

/**
 * Where a bidirectional path's light subpath starts ({@link BdptIntegrator}): at a light of
 * {@link RenderScene#lightsAndSky} chosen by its power, and for a light at infinity on a disc across the
 * sphere around the scene, which holds every bounded primitive and the camera. Next-event estimation samples
 * every light instead, so the light end of its paths is denser by {@link #nextEventFactor}. One per render
 * thread, read by {@link BdptWeights} for the densities and by the integrator to start its subpaths.
 */
final class LightChoice {

    /** The centre and radius of a sphere holding every bounded primitive and the camera. */
    double centreX, centreY, centreZ, radius;

    private Lights lights;
    private CameraModel camera;
    /** Per light: the chance it is chosen, and the sums of the chances. */
    private double[] chance = new double[0], cumulative = new double[0];
    private final double[] box = new double[6];

    /** Reads the lights, the bounded primitives and the camera of a scene being prepared. */
    void prepare(RenderScene scene) {
        lights = scene.lightsAndSky;
        camera = scene.camera;
        bound(scene.primitives);
        chances();
    }

    /**
     * The width of a pixel of a width x height image at the scene's centre, as the camera sees it: the
     * angle between the rays through two neighbouring pixels at the image's centre, times the centre's
     * distance from the eye (half the scene's radius at the least, for a camera inside the scene).
     */
    double pixelWidthAtCentre(int width, int height) {
        double[] ox = new double[2], oy = new double[2], oz = new double[2];
        double[] dx = new double[2], dy = new double[2], dz = new double[2];
        camera.ray(width / 2.0, height / 2.0, 0.5, 0.5, width, height, ox, oy, oz, dx, dy, dz, 0);
        camera.ray(width / 2.0 + 1, height / 2.0, 0.5, 0.5, width, height, ox, oy, oz, dx, dy, dz, 1);
        double cos = dx[0] * dx[1] + dy[0] * dy[1] + dz[0] * dz[1];
        double angle = Math.acos(Math.min(1, cos));
        double ex = centreX - camera.eye().x(), ey = centreY - camera.eye().y(), ez = centreZ - camera.eye().z();
        return angle * Math.max(Math.sqrt(ex * ex + ey * ey + ez * ez), radius / 2);
    }

    /** The light that uniform number u chooses, by power; -1 where the scene has none. */
    int choose(double u) {
        int n = cumulative.length;
        if (n == 0) {
            return -1;
        }
        double target = u * cumulative[n - 1];
        int lo = 0, hi = n - 1;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (cumulative[mid] > target) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        while (chance[lo] == 0 && lo > 0) { // u at the very end of a run of lights that have no chance
            lo--;
        }
        return lo;
    }

    /** The chance light k is chosen. */
    double chance(int k) {
        return chance[k];
    }

    /**
     * The density per solid angle with which a light subpath starts at infinity towards unit direction d
     * (from the scene towards the light): over every light at infinity, its chance times its density.
     */
    double farDensity(double dx, double dy, double dz) {
        double sum = 0;
        for (int k = 0, n = lights.countAtInfinity(); k < n; k++) {
            int i = lights.atInfinity(k);
            sum += chance[i] * lights.pdf(i, 0, 0, 0, dx, dy, dz);
        }
        return sum;
    }

    /**
     * Whether light from infinity along unit direction far (towards the light), leaving its disc across the
     * scene's sphere, may reach point p.
     */
    boolean crossesDisc(double px, double py, double pz, double farX, double farY, double farZ) {
        double qx = px - centreX, qy = py - centreY, qz = pz - centreZ;
        double along = qx * farX + qy * farY + qz * farZ;
        double across2 = qx * qx + qy * qy + qz * qz - along * along;
        return along <= radius && across2 <= radius * radius;
    }

    /**
     * How much denser next-event estimation, which samples every light at every camera point, makes the light
     * end of a path than a light subpath does, which starts from a light chosen by power: 1 / its chance for a
     * light's point (or a delta light's direction); for a direction to light at infinity, the sum of the
     * lights' densities of that direction over the sum weighted by their chances.
     */
    double nextEventFactor(BdptVertex end) {
        if (end.kind == BdptVertex.FAR && !end.deltaLight) {
            double every = 0, chosen = 0;
            for (int k = 0, n = lights.countAtInfinity(); k < n; k++) {
                int i = lights.atInfinity(k);
                double pdf = lights.pdf(i, 0, 0, 0, end.farX, end.farY, end.farZ);
                every += pdf;
                chosen += chance[i] * pdf;
            }
            return chosen > 0 ? every / chosen : 1;
        }
        return end.light >= 0 && chance[end.light] > 0 ? 1 / chance[end.light] : 1;
    }

    private void bound(Primitives primitives) {
        double x0 = camera.eye().x(), y0 = camera.eye().y(), z0 = camera.eye().z();
        double x1 = x0, y1 = y0, z1 = z0;
        for (int p = 0; p < primitives.count(); p++) {
            if (primitives.bounded(p)) {
                primitives.bounds(p, box, 0);
                x0 = Math.min(x0, box[0]);
                y0 = Math.min(y0, box[1]);
                z0 = Math.min(z0, box[2]);
                x1 = Math.max(x1, box[3]);
                y1 = Math.max(y1, box[4]);
                z1 = Math.max(z1, box[5]);
            }
        }
        centreX = (x0 + x1) / 2;
        centreY = (y0 + y1) / 2;
        centreZ = (z0 + z1) / 2;
        double dx = x1 - x0, dy = y1 - y0, dz = z1 - z0;
        radius = Math.max(1, Math.sqrt(dx * dx + dy * dy + dz * dz) / 2);
    }

    /** Each light's chance by its power; every light the same where the powers do not sum to a finite positive. */
    private void chances() {
        int n = lights.count();
        if (chance.length != n) {
            chance = new double[n];
            cumulative = new double[n];
        }
        double total = 0;
        for (int k = 0; k < n; k++) {
            chance[k] = Math.max(0, lights.power(k, radius));
            total += chance[k];
        }
        boolean even = !(total > 0 && total < Double.POSITIVE_INFINITY);
        double sum = 0;
        for (int k = 0; k < n; k++) {
            chance[k] = even ? 1.0 / n : chance[k] / total;
            sum += chance[k];
            cumulative[k] = sum;
        }
    }
}
