package glint.render;

import glint.geometry.Hit;
import glint.shading.Bsdf;
import glint.shading.BsdfSample;
import glint.shading.DirectLight;
import glint.shading.LightSample;
import glint.shading.Mis;
import glint.shading.Rgb;
import glint.shading.Surface;

/**
 * One render thread's path tracer (docs/conventions.md, "Light that bounces"): from the camera ray's
 * hit, a path of surface hits, each lit by every light through a shadow ray where its material has a
 * lobe that is not a delta (next-event estimation), and continued along a direction its BSDF samples;
 * a ray that escapes brings the background's radiance, whatever its depth, so a sky lights the scene.
 * A light with a size is found both by its sample and by the BSDF's, each weighed by the power
 * heuristic (multiple importance sampling); past the last hit a BSDF sample still brings what it
 * finds of such a light, the other half of the light the last hit's sample counted. The path ends
 * at {@code recursion_max} hits, where no direction is sampled, or by Russian roulette on its throughput.
 * Ambient light plays no part. Allocates nothing per ray.
 */
final class PathIntegrator extends Integrator {

    /**
     * The roulette starts at this vertex (1 = the camera ray's hit): the first bounces carry most
     * of the indirect light and are always followed. Chosen, as in common practice, not measured.
     */
    static final int ROULETTE_FROM = 5;
    /** Random dimensions a vertex uses: the direction (a pair), the lobe and the roulette. */
    private static final int DIMENSIONS_PER_VERTEX = 3;
    /**
     * The first dimension of the lights' samples (a pair a light a vertex), past those of any path's
     * directions (3 x 2^20), so that adding a light with a size leaves the other numbers as they were.
     */
    private static final int LIGHT_DIMENSIONS = 3 << 20;

    private final Hit hit = new Hit();
    private final Surface surface = new Surface();
    private final LightSample light = new LightSample();
    private final BsdfSample sampled = new BsdfSample();
    private final Rgb f = new Rgb();
    private final Rgb lit = new Rgb();
    private final Rgb radiance = new Rgb();
    private final PathSamples random = new PathSamples();
    /** The vertex being lit, from 1 (the camera ray's hit): which numbers its lights' samples take. */
    private int vertex;

    @Override
    void prepared(RenderSettings settings) {
    }

    @Override
    void beginPath(int pixelIndex, int frameIndex, int sample, int samples) {
        random.begin(pixelIndex, frameIndex, sample, samples);
    }

    @Override
    PathSamples lightNumbers(int light) {
        random.pair(LIGHT_DIMENSIONS + (vertex - 1) * lights.count() + light);
        return random;
    }

    @Override
    Rgb shadeCamera(int primitive, double t, double ox, double oy, double oz, double dx, double dy, double dz,
                    int hitsLeft) {
        if (primitive == Hit.NONE) {
            escaped(dx, dy, dz, f, radiance);
            return radiance;
        }
        primitives.record(hit, primitive, t);
        follow(ox, oy, oz, dx, dy, dz, hitsLeft);
        if (!Double.isFinite(radiance.r + radiance.g + radiance.b)) { // counted as black
            radiance.set(0, 0, 0);
        }
        return radiance;
    }

    /**
     * The radiance along the ray from o along d whose hit is in {@link #hit}, into {@link #radiance}:
     * the path from there, of at most {@code hitsLeft} hits. Light a BSDF sample meets (a light's
     * body, a sun) counts by the power heuristic against the light's own sample from the vertex it
     * left, as that sample counts against the BSDF's ({@link DirectLight#sum}).
     */
    private void follow(double ox, double oy, double oz, double dx, double dy, double dz, int hitsLeft) {
        double sumR = 0, sumG = 0, sumB = 0;
        double throughputR = 1, throughputG = 1, throughputB = 1;
        Surface s = surface;
        BsdfSample next = sampled;
        double emittedWeight = 1; // of light the ray meets: 1 for the camera ray and after a delta lobe
        for (vertex = 1; ; vertex++) {
            describe(hit, ox, oy, oz, dx, dy, dz, s);
            Bsdf bsdf = materials.bsdf(s.material);
            boolean pastLastHit = vertex > hitsLeft;
            if (materials.emits(s.material) && (!pastLastHit || scene.lightOf[hit.primitive] >= 0)) {
                bsdf.emitted(materials, s, f);
                double k = emittedWeight;
                sumR += bounded(throughputR * f.r * k);
                sumG += bounded(throughputG * f.g * k);
                sumB += bounded(throughputB * f.b * k);
            }
            if (pastLastHit) {
                break;
            }
            if (!materials.isDelta(s.material)) {
                DirectLight.sum(this, lights, materials, bsdf, s, -dx, -dy, -dz, true, light, f, lit);
                sumR += bounded(throughputR * lit.r);
                sumG += bounded(throughputG * lit.g);
                sumB += bounded(throughputB * lit.b);
            }
            // past the last hit only a light with a size is still met: the BSDF's half of its light
            if (vertex >= hitsLeft && (scene.lightsWithSize == 0 || materials.isDelta(s.material))) {
                break;
            }
            int dimension = (vertex - 1) * DIMENSIONS_PER_VERTEX;
            random.pair(dimension);
            if (!bsdf.sample(materials, s, -dx, -dy, -dz, random.u1, random.u2, random.single(dimension + 1), next)
                    || vertex >= hitsLeft && next.delta()) {
                break;
            }
            throughputR = bounded(throughputR * next.weightR);
            throughputG = bounded(throughputG * next.weightG);
            throughputB = bounded(throughputB * next.weightB);
            if (vertex >= ROULETTE_FROM) {
                double survive = Math.min(1, Math.max(throughputR, Math.max(throughputG, throughputB)));
                if (!(random.single(dimension + 2) < survive)) {
                    break;
                }
                throughputR /= survive;
                throughputG /= survive;
                throughputB /= survive;
            }
            ox = next.transmitted() ? s.farX() : s.nearX();
            oy = next.transmitted() ? s.farY() : s.nearY();
            oz = next.transmitted() ? s.farZ() : s.nearZ();
            dx = next.wiX;
            dy = next.wiY;
            dz = next.wiZ;
            if (!nearest(ox, oy, oz, dx, dy, dz, next.transmitted() ? s.skipFar : s.skipNear,
                    next.transmitted() ? s.insideFar : s.insideNear, hit)) {
                escapedFrom(s, next, dx, dy, dz, vertex < hitsLeft);
                sumR += bounded(throughputR * lit.r);
                sumG += bounded(throughputG * lit.g);
                sumB += bounded(throughputB * lit.b);
                break;
            }
            emittedWeight = next.delta() || scene.lightsWithSize == 0 ? 1
                    : weightOfLightMet(s, next, hit.primitive, dx, dy, dz);
        }
        radiance.set(sumR, sumG, sumB);
    }

    /**
     * The most a path's weight, or one vertex's share of its light, holds: far above the largest float a frame
     * stores and far below the largest double, so that the weight of a path through surfaces brighter than 1
     * stays finite, and a vertex that gets no light (0) adds 0, never infinity x 0, NaN (as {@link Rgb} does for
     * Whitted's integrator).
     */
    static final double LARGEST = 1e200;

    private static double bounded(double value) {
        return Math.min(value, LARGEST);
    }

    /**
     * The weight of the light of a light's body that the BSDF sample {@code next} from surface s
     * meets at primitive {@code primitive}: the power heuristic of the BSDF's density against the
     * light's for that direction; 1 for a primitive that is no light's body (its glow has no sample).
     */
    private double weightOfLightMet(Surface s, BsdfSample next, int primitive, double dx, double dy, double dz) {
        int light = scene.lightOf[primitive];
        if (light < 0) {
            return 1;
        }
        return Mis.powerHeuristic(next.pdf, lights.pdf(light, s.px, s.py, s.pz, dx, dy, dz));
    }

    /**
     * The radiance the BSDF sample {@code next} from surface s brings as it escapes the scene along d,
     * into {@link #lit}: the background where {@code background} says (not past the last hit), and
     * each light at infinity it sees (a sun's disc) by the power heuristic against that light's
     * sample (1 after a delta lobe).
     */
    private void escapedFrom(Surface s, BsdfSample next, double dx, double dy, double dz, boolean background) {
        double r = 0, g = 0, b = 0;
        if (background) {
            r = scene.backgroundR;
            g = scene.backgroundG;
            b = scene.backgroundB;
        }
        for (int k = 0, n = lights.countAtInfinity(); k < n; k++) {
            int i = lights.atInfinity(k);
            lights.arriving(i, dx, dy, dz, f);
            double w = next.delta() ? 1 : Mis.powerHeuristic(next.pdf, lights.pdf(i, s.px, s.py, s.pz, dx, dy, dz));
            r += w * f.r;
            g += w * f.g;
            b += w * f.b;
        }
        lit.set(r, g, b);
    }
}
