package glint.render;

import glint.config.Shading;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

/**
 * The yardstick for Glint's frame times: a plain recursive Whitted tracer, as a careful first
 * version would be written, over the same compiled scene. It has the same camera (one ray through
 * each pixel's centre), surfaces (hit points re-projected, rays offset by epsilon max(1, |p|), the
 * surface a ray leaves skipped), cook-torrance shading with the exact Fresnel equations, depth and
 * {@code min_weight}, so it renders the same image ({@code PlainTracerTest}; {@code
 * glint.bench.PairedFrames} and the JMH {@code PlainTracerBenchmark} check it before they time
 * anything). What it leaves out is everything that
 * makes Glint fast: every ray tests every sphere and plane, one ray after another, with no screen
 * ranges, light cones, hierarchy, staged rows or chords inside empty glass spheres. Frames are cut
 * into rows, every {@code threads}-th row to a thread. Cook-torrance only: the phong model is not
 * its business. The shading repeats {@link TracerWorker}'s formulas line for line on purpose (both
 * call {@link Optics} for the terms): a yardstick that ran through the renderer's own methods would
 * time the renderer. In this package to read the compiled scene.
 */
public final class PlainTracer implements AutoCloseable {

    private final ExecutorService pool;
    private final Worker[] workers;

    public PlainTracer(RenderScene scene, int threads) {
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be >= 1, got " + threads);
        }
        RenderSettings settings = scene.settings;
        if (settings.shading() != Shading.COOK_TORRANCE || settings.glassFresnel() != RenderSettings.GlassFresnel.EXACT) {
            throw new IllegalArgumentException("the plain tracer shades cook-torrance with the exact Fresnel equations, got "
                    + settings.shading() + " with " + settings.glassFresnel() + " Fresnel");
        }
        this.pool = Executors.newFixedThreadPool(threads, r -> {
            Thread t = new Thread(r, "plain-tracer");
            t.setDaemon(true);
            return t;
        });
        this.workers = new Worker[threads];
        for (int i = 0; i < threads; i++) {
            workers[i] = new Worker(scene, i, threads);
        }
    }

    /** Renders one frame into {@code frame} and returns when every pixel is written. */
    public void render(FrameBuffer frame) {
        List<Future<?>> rows = new ArrayList<>(workers.length);
        for (Worker worker : workers) {
            rows.add(pool.submit(() -> worker.render(frame)));
        }
        try {
            for (Future<?> done : rows) {
                done.get();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while rendering", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException("a plain tracer thread failed", e.getCause());
        }
    }

    @Override
    public void close() {
        pool.shutdownNow();
    }

    /** One thread's tracer: its rows, and the radiance its last {@link #trace} brought back. */
    private static final class Worker {

        private static final double INV_PI = 1 / Math.PI;
        private static final int NONE = 0;

        private final RenderScene s;
        private final int firstRow, rowStep, depth;
        private final double epsilon, minWeight;
        private final double[] refracted = new double[3];
        private double outR, outG, outB;

        Worker(RenderScene scene, int firstRow, int rowStep) {
            this.s = scene;
            this.firstRow = firstRow;
            this.rowStep = rowStep;
            this.depth = scene.settings.recursionMax();
            this.epsilon = scene.settings.epsilon();
            this.minWeight = scene.settings.minWeight();
        }

        void render(FrameBuffer frame) {
            CameraBasis c = s.camera;
            int width = frame.width(), height = frame.height();
            double halfWidth = c.tanHalfFov, halfHeight = halfWidth * height / width;
            for (int y = firstRow; y < height; y += rowStep) {
                double sy = (y + 0.5) * (-2 * halfHeight / height) + halfHeight;
                for (int x = 0; x < width; x++) {
                    double sx = (x + 0.5) * (2 * halfWidth / width) - halfWidth;
                    double dx = c.forwardX + sx * c.rightX + sy * c.upX;
                    double dy = c.forwardY + sx * c.rightY + sy * c.upY;
                    double dz = c.forwardZ + sx * c.rightZ + sy * c.upZ;
                    double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
                    trace(c.eyeX, c.eyeY, c.eyeZ, dx * inv, dy * inv, dz * inv, depth, 1, NONE);
                    frame.set(x, y, outR, outG, outB);
                }
            }
        }

        /**
         * The radiance along the unit ray from o along d into out: {@code hitsLeft} surface hits
         * may still be shaded, {@code weight} is the path's throughput, {@code skip} the surface
         * the ray leaves on its outer side (sphere i + 1, plane -(i + 1), or NONE).
         */
        private void trace(double ox, double oy, double oz, double dx, double dy, double dz, int hitsLeft,
                           double weight, int skip) {
            double nearest = Intersect.MISS;
            int surface = NONE;
            for (int i = 0; i < s.sphereCount; i++) {
                if (skip == i + 1) {
                    continue;
                }
                int k = 4 * i;
                double t = Intersect.sphereBefore(s.spheres[k], s.spheres[k + 1], s.spheres[k + 2], s.spheres[k + 3],
                        ox, oy, oz, dx, dy, dz, nearest);
                if (t < nearest) {
                    nearest = t;
                    surface = i + 1;
                }
            }
            for (int i = 0; i < s.planeCount; i++) {
                if (skip == -(i + 1)) {
                    continue;
                }
                int k = 4 * i;
                double t = Intersect.planeBefore(s.planes[k], s.planes[k + 1], s.planes[k + 2], s.planes[k + 3],
                        ox, oy, oz, dx, dy, dz, nearest);
                if (t < nearest) {
                    nearest = t;
                    surface = -(i + 1);
                }
            }
            if (surface == NONE) {
                outR = s.backgroundR;
                outG = s.backgroundG;
                outB = s.backgroundB;
                return;
            }
            shade(surface, ox + nearest * dx, oy + nearest * dy, oz + nearest * dz, dx, dy, dz, hitsLeft, weight);
        }

        /** Shades the hit at p (not yet re-projected) on {@code surface} of a ray along d. */
        private void shade(int surface, double px, double py, double pz, double dx, double dy, double dz,
                           int hitsLeft, double weight) {
            double offset = epsilon * Math.max(1, Math.sqrt(px * px + py * py + pz * pz));
            double nx, ny, nz;
            int material;
            if (surface > 0) {
                int k = 4 * (surface - 1);
                double cx = s.spheres[k], cy = s.spheres[k + 1], cz = s.spheres[k + 2], r = s.spheres[k + 3];
                double ex = px - cx, ey = py - cy, ez = pz - cz;
                double inv = 1 / Math.sqrt(ex * ex + ey * ey + ez * ez);
                nx = ex * inv;
                ny = ey * inv;
                nz = ez * inv;
                px = cx + r * nx;
                py = cy + r * ny;
                pz = cz + r * nz;
                material = s.sphereMaterial[surface - 1];
            } else {
                int k = 4 * (-surface - 1);
                nx = s.planes[k];
                ny = s.planes[k + 1];
                nz = s.planes[k + 2];
                double off = nx * px + ny * py + nz * pz - s.planes[k + 3];
                px -= off * nx;
                py -= off * ny;
                pz -= off * nz;
                material = s.planeMaterial[-surface - 1];
            }
            double cosIncident = -(dx * nx + dy * ny + dz * nz);
            boolean front = cosIncident >= 0;
            if (!front) {
                nx = -nx;
                ny = -ny;
                nz = -nz;
                cosIncident = -cosIncident;
            }
            // rays back to the side the ray came from leave the surface on its outer side, except
            // inside a sphere; rays through it, the other way round
            int skipNear = surface < 0 || front ? surface : NONE;
            int skipFar = surface < 0 || !front ? surface : NONE;
            double ox = px + offset * nx, oy = py + offset * ny, oz = pz + offset * nz;
            switch (s.materialType[material]) {
                case RenderScene.MATTE -> matte(material, px, py, pz, nx, ny, nz, ox, oy, oz, skipNear);
                case RenderScene.METAL -> metal(material, px, py, pz, nx, ny, nz, ox, oy, oz, dx, dy, dz, cosIncident,
                        hitsLeft, weight, skipNear);
                default -> glass(material, px, py, pz, nx, ny, nz, offset, dx, dy, dz, cosIncident, front, hitsLeft,
                        weight, skipNear, skipFar);
            }
        }

        private void matte(int m, double px, double py, double pz, double nx, double ny, double nz, double ox,
                           double oy, double oz, int skip) {
            double sumR = 0, sumG = 0, sumB = 0;
            for (int light = 0; light < s.lightCount; light++) {
                double[] sample = lightSample(light, px, py, pz);
                double cosLight = sample[0] * nx + sample[1] * ny + sample[2] * nz;
                if (cosLight > 0 && !shadowed(ox, oy, oz, sample[0], sample[1], sample[2], sample[3], skip)) {
                    sumR += sample[4] * cosLight;
                    sumG += sample[5] * cosLight;
                    sumB += sample[6] * cosLight;
                }
            }
            int c = 3 * m;
            outR = s.materialColor[c] * (sumR * INV_PI + s.ambientR);
            outG = s.materialColor[c + 1] * (sumG * INV_PI + s.ambientG);
            outB = s.materialColor[c + 2] * (sumB * INV_PI + s.ambientB);
        }

        private void metal(int m, double px, double py, double pz, double nx, double ny, double nz, double ox,
                           double oy, double oz, double dx, double dy, double dz, double cosView, int hitsLeft,
                           double weight, int skip) {
            int c = 3 * m;
            double f0R = s.materialColor[c], f0G = s.materialColor[c + 1], f0B = s.materialColor[c + 2];
            double alpha = s.alpha[m];
            double sumR = 0, sumG = 0, sumB = 0;
            for (int light = 0; alpha > 0 && cosView > 0 && light < s.lightCount; light++) {
                double[] l = lightSample(light, px, py, pz);
                double cosLight = l[0] * nx + l[1] * ny + l[2] * nz;
                if (cosLight <= 0 || shadowed(ox, oy, oz, l[0], l[1], l[2], l[3], skip)) {
                    continue;
                }
                double hx = l[0] - dx, hy = l[1] - dy, hz = l[2] - dz;
                double inv = 1 / Math.sqrt(hx * hx + hy * hy + hz * hz);
                double cosHalf = (hx * nx + hy * ny + hz * nz) * inv;
                double cosViewHalf = Math.max(0, -(hx * dx + hy * dy + hz * dz) * inv);
                double specular = Optics.ggx(cosHalf, alpha) * Optics.smithVisibility(cosLight, cosView, alpha) * cosLight;
                sumR += specular * Optics.schlick(f0R, cosViewHalf) * l[4];
                sumG += specular * Optics.schlick(f0G, cosViewHalf) * l[5];
                sumB += specular * Optics.schlick(f0B, cosViewHalf) * l[6];
            }
            if (hitsLeft > 1) {
                double fR = Optics.schlick(f0R, cosView), fG = Optics.schlick(f0G, cosView), fB = Optics.schlick(f0B, cosView);
                double childWeight = weight * Math.max(fR, Math.max(fG, fB));
                if (childWeight >= minWeight) {
                    double k = 2 * cosView;
                    trace(ox, oy, oz, dx + k * nx, dy + k * ny, dz + k * nz, hitsLeft - 1, childWeight, skip);
                    sumR += fR * outR;
                    sumG += fG * outG;
                    sumB += fB * outB;
                }
            }
            outR = sumR;
            outG = sumG;
            outB = sumB;
        }

        private void glass(int m, double px, double py, double pz, double nx, double ny, double nz, double offset,
                           double dx, double dy, double dz, double cosIncident, boolean entering, int hitsLeft,
                           double weight, int skipNear, int skipFar) {
            double sumR = 0, sumG = 0, sumB = 0;
            if (hitsLeft > 1) {
                double eta = entering ? 1 / s.ior[m] : s.ior[m];
                double reflectance = Optics.fresnelDielectric(cosIncident, eta);
                double k = 2 * cosIncident;
                if (weight * reflectance >= minWeight) {
                    trace(px + offset * nx, py + offset * ny, pz + offset * nz, dx + k * nx, dy + k * ny, dz + k * nz,
                            hitsLeft - 1, weight * reflectance, skipNear);
                    sumR += reflectance * outR;
                    sumG += reflectance * outG;
                    sumB += reflectance * outB;
                }
                int c = 3 * m;
                double tR = (1 - reflectance) * s.materialColor[c];
                double tG = (1 - reflectance) * s.materialColor[c + 1];
                double tB = (1 - reflectance) * s.materialColor[c + 2];
                double childWeight = weight * Math.max(tR, Math.max(tG, tB));
                if (reflectance < 1 && childWeight >= minWeight) {
                    if (Optics.refract(dx, dy, dz, nx, ny, nz, cosIncident, eta, refracted)) {
                        trace(px - offset * nx, py - offset * ny, pz - offset * nz, refracted[0], refracted[1],
                                refracted[2], hitsLeft - 1, childWeight, skipFar);
                    } else {
                        trace(px + offset * nx, py + offset * ny, pz + offset * nz, dx + k * nx, dy + k * ny,
                                dz + k * nz, hitsLeft - 1, childWeight, skipNear);
                    }
                    sumR += tR * outR;
                    sumG += tG * outG;
                    sumB += tB * outB;
                }
            }
            outR = sumR;
            outG = sumG;
            outB = sumB;
        }

        private final double[] sample = new double[7];

        /**
         * Light {@code i} seen from p: {unit direction to it (3), distance, irradiance on a surface
         * facing it (3)}; a point light at p itself gives a zero direction.
         */
        private double[] lightSample(int i, double px, double py, double pz) {
            int j = 3 * i;
            double scale = 1;
            if (s.lightIsPoint[i]) {
                double lx = s.lightVector[j] - px, ly = s.lightVector[j + 1] - py, lz = s.lightVector[j + 2] - pz;
                double distance2 = lx * lx + ly * ly + lz * lz;
                double inv = distance2 == 0 ? 0 : 1 / Math.sqrt(distance2);
                sample[0] = lx * inv;
                sample[1] = ly * inv;
                sample[2] = lz * inv;
                sample[3] = distance2 * inv;
                scale = inv * inv;
            } else {
                sample[0] = s.lightVector[j];
                sample[1] = s.lightVector[j + 1];
                sample[2] = s.lightVector[j + 2];
                sample[3] = Double.POSITIVE_INFINITY;
            }
            sample[4] = s.lightPower[j] * scale;
            sample[5] = s.lightPower[j + 1] * scale;
            sample[6] = s.lightPower[j + 2] * scale;
            return sample;
        }

        /** Whether any surface but {@code skip} lies on the ray from o along d before tMax. */
        private boolean shadowed(double ox, double oy, double oz, double dx, double dy, double dz, double tMax,
                                 int skip) {
            for (int i = 0; i < s.sphereCount; i++) {
                int k = 4 * i;
                if (skip != i + 1 && Intersect.sphereBefore(s.spheres[k], s.spheres[k + 1], s.spheres[k + 2],
                        s.spheres[k + 3], ox, oy, oz, dx, dy, dz, tMax) < tMax) {
                    return true;
                }
            }
            for (int i = 0; i < s.planeCount; i++) {
                int k = 4 * i;
                if (skip != -(i + 1) && Intersect.planeBefore(s.planes[k], s.planes[k + 1], s.planes[k + 2],
                        s.planes[k + 3], ox, oy, oz, dx, dy, dz, tMax) < tMax) {
                    return true;
                }
            }
            return false;
        }
    }
}
