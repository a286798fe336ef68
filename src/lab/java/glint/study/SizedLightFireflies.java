package glint.study;

import glint.math.Vector3d;
import glint.render.Tracer;
import glint.scene.Scene;
import glint.shading.BsdfSample;
import glint.shading.Conductor;
import glint.shading.Lambert;
import glint.shading.LightSample;
import glint.shading.Lights;
import glint.shading.Materials;
import glint.shading.MatteResponse;
import glint.shading.MetalResponse;
import glint.shading.Mis;
import glint.shading.Rgb;
import glint.shading.SphereLightSampler;
import glint.shading.Surface;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;

/**
 * Fireflies from a glossy bounce to a small light with a size: the scene of {@link Fireflies} (matte
 * floor, white metal wall, black background) with its point light made a sphere light of the same
 * power and radius r. One floor point, {@link #POINT}, is estimated by paths of two hits (the floor,
 * then what its cosine sample meets) in three ways that differ only in how light with a size is
 * found at each hit:
 * <ul>
 *   <li>{@link Strategy#MIS}: by its sample and by the BSDF's, each weighed by the power heuristic
 *       (Veach 1997), what Glint's path integrator does;</li>
 *   <li>{@link Strategy#LIGHT}: by its sample only; a BSDF sample that meets the light counts nothing
 *       (a renderer without MIS that treats the light as a point with a size);</li>
 *   <li>{@link Strategy#BSDF}: by the BSDF's sample only, no light samples.</li>
 * </ul>
 * Each is this study's own estimator over the product's pieces: the light is sampled and its density
 * found by {@link SphereLightSampler} through {@link Lights}, the floor and wall scatter by
 * {@link Lambert} and {@link Conductor} through {@link Materials}. The geometry is solved in closed form:
 * nothing lies between the floor, the wall and the light (the light is in front of the wall and above
 * the floor), so every shadow ray passes, and a direction meets the light exactly where the light's
 * density for it is not 0. {@link #render} measures the product's path integrator at the same point.
 */
final class SizedLightFireflies {

    /** The floor point studied: the one the camera of {@link Fireflies} looks at. */
    static final Vector3d POINT = new Vector3d(0.8, 0, 0.1);
    /** Where the floor point is seen from (the camera of {@link Fireflies}). */
    static final Vector3d EYE = new Vector3d(0.8, 1.6, -1.2);

    enum Strategy {
        MIS("light and BSDF samples, power heuristic (Glint)"),
        LIGHT("light samples only"),
        BSDF("BSDF samples only");

        final String label;

        Strategy(String label) {
            this.label = label;
        }
    }

    private final Lights lights;
    private final Materials materials;
    private final double radiance;
    private final Surface floor = new Surface(), wall = new Surface();
    private final LightSample light = new LightSample();
    private final BsdfSample bsdf = new BsdfSample();
    private final Rgb f = new Rgb();
    private final Lambert lambert = new Lambert();
    private final Conductor conductor = new Conductor();
    private final double woX, woY, woZ;

    /** The scene with a wall of {@code roughness} and a sphere light of {@code radius}. */
    SizedLightFireflies(double roughness, double radius) {
        radiance = Fireflies.INTENSITY / (Math.PI * radius * radius);
        Vector3d c = Fireflies.LIGHT;
        lights = Lights.of(List.of(new Lights.Light(new SphereLightSampler(),
                SphereLightSampler.data(c.x(), c.y(), c.z(), radius, radiance, radiance, radiance), null)));
        materials = Materials.of(List.of(
                new Materials.Material(lambert, new MatteResponse(), new Vector3d(Fireflies.ALBEDO, Fireflies.ALBEDO,
                        Fireflies.ALBEDO), 1, 0, 0, 1, 1.5, new double[0]),
                new Materials.Material(conductor, new MetalResponse(), Vector3d.ONE, 0, 1, 0, 1, 1.5,
                        Conductor.parameters(roughness))));
        Vector3d wo = EYE.sub(POINT).normalize();
        woX = wo.x();
        woY = wo.y();
        woZ = wo.z();
        floor.px = POINT.x();
        floor.py = POINT.y();
        floor.pz = POINT.z();
        floor.ny = 1;
        floor.cosIncident = woY;
        floor.front = true;
        floor.material = 0;
        wall.nx = 1;
        wall.front = true;
        wall.material = 1;
    }

    /** {@code n} seeded samples of the floor point's radiance (grey: channel 0) by {@code strategy}. */
    double[] samples(Strategy strategy, int n, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        double[] out = new double[n];
        for (int i = 0; i < n; i++) {
            out[i] = sample(strategy, random);
        }
        return out;
    }

    private double sample(Strategy strategy, SplittableRandom random) {
        // the floor: its light sample, then its cosine sample
        double value = lit(strategy, lambert, floor, woX, woY, woZ, random.nextDouble(), random.nextDouble());
        if (!lambert.sample(materials, floor, woX, woY, woZ, random.nextDouble(), random.nextDouble(),
                random.nextDouble(), bsdf)) {
            return value;
        }
        double dx = bsdf.wiX, dy = bsdf.wiY, dz = bsdf.wiZ, weight = bsdf.weightR;
        double lightPdf = lights.pdf(0, floor.px, floor.py, floor.pz, dx, dy, dz);
        if (lightPdf > 0) { // it meets the light
            return value + weight * radiance * found(strategy, bsdf.pdf, lightPdf);
        }
        if (!(dx < 0)) { // away from the wall: the black background
            return value;
        }
        // the wall at x = 0, the path's second and last hit: its light sample and the light its BSDF sample meets
        double t = -floor.px / dx;
        wall.px = 0;
        wall.py = floor.py + t * dy;
        wall.pz = floor.pz + t * dz;
        wall.cosIncident = -dx;
        double at = lit(strategy, conductor, wall, -dx, -dy, -dz, random.nextDouble(), random.nextDouble());
        if (conductor.sample(materials, wall, -dx, -dy, -dz, random.nextDouble(), random.nextDouble(),
                random.nextDouble(), bsdf)) {
            double wallLightPdf = lights.pdf(0, wall.px, wall.py, wall.pz, bsdf.wiX, bsdf.wiY, bsdf.wiZ);
            if (wallLightPdf > 0) {
                at += bsdf.weightR * radiance * found(strategy, bsdf.pdf, wallLightPdf);
            }
        }
        return value + weight * at;
    }

    /** The light's sample at s through the BSDF towards wo, weighed as the strategy weighs it. */
    private double lit(Strategy strategy, glint.shading.Bsdf b, Surface s, double ox, double oy, double oz, double u1,
                       double u2) {
        if (strategy == Strategy.BSDF || !lights.sample(0, s.px, s.py, s.pz, u1, u2, light)) {
            return 0;
        }
        double cos = light.dirX * s.nx + light.dirY * s.ny + light.dirZ * s.nz;
        if (!(cos > 0)) {
            return 0;
        }
        b.evaluate(materials, s, ox, oy, oz, light.dirX, light.dirY, light.dirZ, f);
        double k = f.r * light.irradianceR * cos;
        if (strategy == Strategy.MIS && k > 0) {
            k *= Mis.powerHeuristic(light.pdf, b.pdf(materials, s, ox, oy, oz, light.dirX, light.dirY, light.dirZ));
        }
        return k;
    }

    /** The weight of light a BSDF sample of density {@code pdf} meets, the light's own density being {@code lightPdf}. */
    private static double found(Strategy strategy, double pdf, double lightPdf) {
        return switch (strategy) {
            case MIS -> Mis.powerHeuristic(pdf, lightPdf);
            case LIGHT -> 0;
            case BSDF -> 1;
        };
    }

    // ---- the product's path integrator at the same point --------------------------------------------

    /** Pixels of the product's render: all see {@link #POINT}, within 10^-5 of it. */
    static final int PIXELS = 8;

    static String yaml(double roughness, double radius) {
        Vector3d l = Fireflies.LIGHT;
        return String.format(Locale.ROOT, """
                camera: {position: [%s, %s, %s], look_at: [%s, %s, %s], fov: 0.0003}
                background: [0, 0, 0]
                lights:
                  - {type: point, position: [%s, %s, %s], radius: %s, intensity: %s}
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [%s, %s, %s]}}
                  - {type: plane, point: [0, 0, 0], normal: [1, 0, 0], material: {type: metal, color: [1, 1, 1], roughness: %s}}
                """, EYE.x(), EYE.y(), EYE.z(), POINT.x(), POINT.y(), POINT.z(), l.x(), l.y(), l.z(), radius,
                Fireflies.INTENSITY, Fireflies.ALBEDO, Fireflies.ALBEDO, Fireflies.ALBEDO, roughness);
    }

    /**
     * The product's path integrator (2 hits) at the floor point: {@link #PIXELS}^2 pixels that all see it,
     * {@code samples} (a perfect square) each.
     */
    static PassSamples render(double roughness, double radius, int samples, Tracer tracer) {
        Scene scene = PassSamples.parse("sized-light-fireflies.yaml", yaml(roughness, radius));
        return PassSamples.render(scene, PIXELS, PIXELS, samples, 2, tracer);
    }

    /** Mean, standard error, spread of a sample over the mean and largest sample over the mean of samples. */
    record Stats(double mean, double standardError, double relativeStd, double maxOverMean, long count) {

        static Stats of(double[] v) {
            double sum = 0, max = 0;
            for (double x : v) {
                sum += x;
                max = Math.max(max, x);
            }
            double mean = sum / v.length, q = 0;
            for (double x : v) {
                q += (x - mean) * (x - mean);
            }
            double std = Math.sqrt(q / (v.length - 1));
            return new Stats(mean, std / Math.sqrt(v.length), std / mean, max / mean, v.length);
        }

        static Stats of(PassSamples s) {
            return new Stats(s.mean(), s.standardError(), s.sampleStd() / s.mean(), s.max() / s.mean(),
                    (long) s.values.length * s.samples);
        }
    }
}
