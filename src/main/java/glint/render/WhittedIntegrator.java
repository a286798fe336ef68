package glint.render;

import glint.geometry.Hit;
import glint.shading.CookTorrance;
import glint.shading.Lights;
import glint.shading.Materials;
import glint.shading.Optics;
import glint.shading.Phong;
import glint.shading.Rgb;
import glint.shading.ShadingContext;
import glint.shading.ShadingModel;
import glint.shading.SingleRays;
import glint.shading.Surface;

/**
 * One render thread's Whitted tracer: follows a ray to its nearest hit, describes the surface
 * there and lets the shading model send radiance back, tracing reflected and refracted rays by
 * recursion. Its scratch values live in one {@link PathVertex} a level, so nothing is allocated per
 * ray. All vectors are world space, directions unit length.
 */
final class WhittedIntegrator extends Integrator implements ShadingContext {

    private static final ShadingModel COOK_TORRANCE = new CookTorrance();
    private static final ShadingModel PHONG = new Phong();

    private ShadingModel model;
    private PathVertex[] vertices = new PathVertex[0];
    private final InsideWalk walk = new InsideWalk(this);

    private double minWeight;
    private boolean roulette;

    // the camera ray whose path is being traced, which seeds its random decisions, and how many it made
    private int pathPixel, pathFrame, pathSample, pathDraws;
    /**
     * The numbers of the samples of lights with a size, each stratified over the pixel's samples: light
     * i at depth k of the path (the camera ray's hit is depth 0) takes dimension k x lights + i, so that
     * every hit's lights are evenly covered by the pixel's samples, and a hit's numbers do not depend on
     * which other rays the path traced (a deeper or less pruned image draws the same ones).
     */
    private final PathSamples lightSamples = new PathSamples();
    /** The depth of the vertex being lit, set by {@link #direct}. */
    private int lightDepth;
    private int recursionMax;
    /** Scratch: a light at infinity seen by an escaping ray. */
    private final Rgb arriving = new Rgb();

    @Override
    void prepared(RenderSettings settings) {
        model = settings.shading() == Shading.PHONG ? PHONG : COOK_TORRANCE;
        minWeight = settings.minWeight();
        recursionMax = settings.recursionMax();
        roulette = settings.pruning() == RenderSettings.Pruning.ROULETTE;
        if (vertices.length <= settings.recursionMax()) {
            PathVertex[] grown = new PathVertex[settings.recursionMax() + 1];
            for (int i = 0; i < grown.length; i++) {
                grown[i] = i < vertices.length ? vertices[i] : new PathVertex();
            }
            vertices = grown;
        }
        walk.prepare(settings.recursionMax());
    }

    /** Starts the path of camera ray (pixel, frame, sample); the roulette's draws follow from it. */
    @Override
    void beginPath(int pixelIndex, int frameIndex, int sample, int samples) {
        pathPixel = pixelIndex;
        pathFrame = frameIndex;
        pathSample = sample;
        pathDraws = 0;
        if (scene.lightsWithSize > 0) {
            lightSamples.begin(pixelIndex, frameIndex, sample, samples);
        }
    }

    @Override
    PathSamples lightNumbers(int light) {
        lightSamples.pair(lightDepth * lights.count() + light);
        return lightSamples;
    }

    /**
     * What a child ray of path weight {@code childWeight} counts for: 1 when it is at least
     * min_weight (traced as it is, no number drawn); below, with roulette, 1 / q with probability
     * q = childWeight / min_weight (its weight becomes min_weight) and 0 otherwise, which keeps the
     * expected value; with the plain cut-off, 0. The caller traces the child with weight
     * {@code childWeight x keep} and scales its radiance by {@code keep} when that is above 0.
     */
    double keep(double childWeight) {
        if (childWeight >= minWeight) {
            return 1;
        }
        if (!roulette || !(childWeight > 0)) {
            return 0;
        }
        double q = childWeight / minWeight;
        return SamplePattern.pathUniform(pathPixel, pathFrame, pathSample, pathDraws++) < q ? 1 / q : 0;
    }

    /**
     * The radiance arriving at o along -d: {@code hitsLeft} (>= 1) surface hits this path may
     * still shade, {@code weight} its throughput so far, {@code skip} the primitive the ray leaves
     * on its outer side and {@code inside} the closed primitive it travels inside of ({@link Hit#NONE}
     * for none). The result is the scratch value of level
     * {@code hitsLeft}: read it before tracing another ray from the same level.
     */
    Rgb trace(double ox, double oy, double oz, double dx, double dy, double dz, int hitsLeft, double weight,
              int skip, int inside) {
        PathVertex v = vertices[hitsLeft];
        if (!nearest(ox, oy, oz, dx, dy, dz, skip, inside, v.hit)) {
            escaped(dx, dy, dz, arriving, v.radiance);
            return v.radiance;
        }
        return shadeHit(v, ox, oy, oz, dx, dy, dz, hitsLeft, weight);
    }

    /** {@link #trace} for a camera ray whose nearest hit is already known. */
    @Override
    Rgb shadeCamera(int primitive, double t, double ox, double oy, double oz, double dx, double dy, double dz,
                    int hitsLeft) {
        PathVertex v = vertices[hitsLeft];
        if (primitive == Hit.NONE) {
            escaped(dx, dy, dz, arriving, v.radiance);
            return v.radiance;
        }
        primitives.record(v.hit, primitive, t);
        return shadeHit(v, ox, oy, oz, dx, dy, dz, hitsLeft, 1);
    }

    /** The radiance vertex v's hit (found by the unit ray from o along d) sends back along the ray. */
    private Rgb shadeHit(PathVertex v, double ox, double oy, double oz, double dx, double dy, double dz,
                         int hitsLeft, double weight) {
        Surface s = v.surface;
        Rgb sum = v.sum;
        describe(v.hit, ox, oy, oz, dx, dy, dz, s);
        direct(v, dx, dy, dz, hitsLeft);
        if (hitsLeft > 1) {
            SingleRays rays = v.rays;
            model.specular(this, s, rays);
            scatter(s, rays, v.refracted, dx, dy, dz, hitsLeft, weight, sum);
        }
        v.radiance.set(sum.r, sum.g, sum.b);
        return v.radiance;
    }

    /**
     * The light vertex v's surface sends back along d by itself, into its sum: the shading model's
     * {@code direct}, whose samples of lights with a size take the numbers of the vertex's depth
     * ({@link #lightNumbers}), {@code hitsLeft} the hits the path may still shade there.
     */
    void direct(PathVertex v, double dx, double dy, double dz, int hitsLeft) {
        lightDepth = recursionMax - hitsLeft;
        model.direct(this, v.surface, dx, dy, dz, v.light, v.f, v.sum);
    }

    /**
     * Traces the ray reflected at s (mirror direction of d about the facing normal) and returns its
     * radiance.
     */
    Rgb traceReflected(Surface s, double dx, double dy, double dz, int hitsLeft, double weight) {
        double k = 2 * s.cosIncident;
        return trace(s.nearX(), s.nearY(), s.nearZ(), dx + k * s.nx, dy + k * s.ny, dz + k * s.nz, hitsLeft - 1,
                weight, s.skipNear, s.insideNear);
    }

    /**
     * Adds to {@code sum} the light mirrored at s (the mirror direction of d), weighted by the
     * factor fR, fG, fB per channel: the ray, of path weight weight x the largest factor, is traced
     * if {@link #keep} keeps it. {@code hitsLeft} counts this surface.
     */
    void addReflected(Surface s, double dx, double dy, double dz, int hitsLeft, double weight, double fR,
                             double fG, double fB, Rgb sum) {
        double childWeight = weight * Math.max(fR, Math.max(fG, fB));
        double keep = keep(childWeight);
        if (keep > 0) {
            Rgb reflected = traceReflected(s, dx, dy, dz, hitsLeft, childWeight * keep);
            sum.r += keep * fR * reflected.r;
            sum.g += keep * fG * reflected.g;
            sum.b += keep * fB * reflected.b;
        }
    }

    /**
     * Adds to {@code sum} what the single rays of surface s (of factors {@code rays}) bring back: the
     * reflected ray through {@link #addReflected}, then the refracted one (its direction written into
     * {@code refracted}), of path weight weight x the tint's largest channel, traced if {@link #keep}
     * keeps it. {@code hitsLeft} (at least 2) counts this surface.
     */
    private void scatter(Surface s, SingleRays rays, double[] refracted, double dx, double dy, double dz,
                         int hitsLeft, double weight, Rgb sum) {
        if (rays.reflectMax() > 0) {
            addReflected(s, dx, dy, dz, hitsLeft, weight, rays.reflectR, rays.reflectG, rays.reflectB, sum);
        }
        double childWeight = weight * rays.transmitMax();
        double keep = childWeight > 0 ? keep(childWeight) : 0;
        if (keep > 0) {
            Rgb radiance = traceRefracted(s, rays.eta, refracted, dx, dy, dz, hitsLeft, childWeight * keep);
            sum.r += keep * rays.transmitR * radiance.r;
            sum.g += keep * rays.transmitG * radiance.g;
            sum.b += keep * rays.transmitB * radiance.b;
        }
    }

    /**
     * Traces the ray refracted through surface s (ratio {@code eta}) along the direction it writes
     * into {@code t}, its origin offset to the far side; past the critical angle, the reflected one.
     * Into a closed primitive nothing else reaches into, the ray walks its inside ({@link InsideWalk}).
     * Returns its radiance.
     */
    private Rgb traceRefracted(Surface s, double eta, double[] t, double dx, double dy, double dz, int hitsLeft,
                               double weight) {
        if (!Optics.refract(dx, dy, dz, s.nx, s.ny, s.nz, s.cosIncident, eta, t)) {
            return traceReflected(s, dx, dy, dz, hitsLeft, weight);
        }
        if (s.insideFar != Hit.NONE && aggregate.emptyInside(s.insideFar)) {
            return walk.trace(s, t[0], t[1], t[2], hitsLeft - 1, weight);
        }
        return trace(s.farX(), s.farY(), s.farZ(), t[0], t[1], t[2], hitsLeft - 1, weight, s.skipFar, s.insideFar);
    }

    ShadingModel model() {
        return model;
    }

    @Override
    public Materials materials() {
        return materials;
    }

    @Override
    public Lights lights() {
        return lights;
    }

    @Override
    public double ambient(int channel) {
        return channel == 0 ? scene.ambientR : channel == 1 ? scene.ambientG : scene.ambientB;
    }
}
