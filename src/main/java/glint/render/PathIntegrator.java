package glint.render;

import glint.geometry.Hit;
import glint.shading.Bsdf;
import glint.shading.BsdfSample;
import glint.shading.DirectLight;
import glint.shading.LightSample;
import glint.shading.Rgb;
import glint.shading.Surface;

/**
 * One render thread's path tracer (docs/conventions.md, "Light that bounces"): from the camera ray's
 * hit, a path of surface hits, each lit by every light through a shadow ray where its material has a
 * lobe that is not a delta (next-event estimation), and continued along a direction its BSDF samples;
 * a ray that escapes brings the background's radiance, whatever its depth, so a sky lights the scene.
 * The path ends at {@code recursion_max} hits, where no direction is sampled, or by Russian roulette
 * on its throughput. Ambient light plays no part. Allocates nothing per ray.
 */
final class PathIntegrator extends Integrator {

    /**
     * The roulette starts at this vertex (1 = the camera ray's hit): the first bounces carry most
     * of the indirect light and are always followed. Chosen, as in common practice, not measured.
     */
    static final int ROULETTE_FROM = 5;
    /** Random dimensions a vertex uses: the direction (a pair), the lobe and the roulette. */
    private static final int DIMENSIONS_PER_VERTEX = 3;

    private final Hit hit = new Hit();
    private final Surface surface = new Surface();
    private final LightSample light = new LightSample();
    private final BsdfSample sampled = new BsdfSample();
    private final Rgb f = new Rgb();
    private final Rgb lit = new Rgb();
    private final Rgb radiance = new Rgb();
    private final PathSamples random = new PathSamples();

    @Override
    void prepared(RenderSettings settings) {
    }

    @Override
    void beginPath(int pixelIndex, int frameIndex, int sample, int samples) {
        random.begin(pixelIndex, frameIndex, sample, samples);
    }

    @Override
    Rgb shadeCamera(int primitive, double t, double ox, double oy, double oz, double dx, double dy, double dz,
                    int hitsLeft) {
        if (primitive == Hit.NONE) {
            radiance.set(scene.backgroundR, scene.backgroundG, scene.backgroundB);
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
     * the path from there, of at most {@code hitsLeft} hits.
     */
    private void follow(double ox, double oy, double oz, double dx, double dy, double dz, int hitsLeft) {
        double sumR = 0, sumG = 0, sumB = 0;
        double throughputR = 1, throughputG = 1, throughputB = 1;
        Surface s = surface;
        BsdfSample next = sampled;
        for (int vertex = 1; ; vertex++) {
            describe(hit, ox, oy, oz, dx, dy, dz, s);
            Bsdf bsdf = materials.bsdf(s.material);
            if (materials.emits(s.material)) {
                bsdf.emitted(materials, s, f);
                sumR += throughputR * f.r;
                sumG += throughputG * f.g;
                sumB += throughputB * f.b;
            }
            if (!materials.isDelta(s.material)) {
                DirectLight.sum(this, lights, materials, bsdf, s, -dx, -dy, -dz, light, f, lit);
                sumR += throughputR * lit.r;
                sumG += throughputG * lit.g;
                sumB += throughputB * lit.b;
            }
            if (vertex >= hitsLeft) {
                break;
            }
            int dimension = (vertex - 1) * DIMENSIONS_PER_VERTEX;
            random.pair(dimension);
            if (!bsdf.sample(materials, s, -dx, -dy, -dz, random.u1, random.u2, random.single(dimension + 1), next)) {
                break;
            }
            throughputR *= next.weightR;
            throughputG *= next.weightG;
            throughputB *= next.weightB;
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
                sumR += throughputR * scene.backgroundR;
                sumG += throughputG * scene.backgroundG;
                sumB += throughputB * scene.backgroundB;
                break;
            }
        }
        radiance.set(sumR, sumG, sumB);
    }
}
