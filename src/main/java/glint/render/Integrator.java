package glint.render;

import glint.config.Shading;
import glint.accel.Aggregate;
import glint.accel.Candidates;
import glint.accel.Frustum;
import glint.geometry.Hit;
import glint.geometry.Intersect;
import glint.geometry.Primitives;
import glint.accel.TraversalStack;
import glint.shading.CookTorrance;
import glint.shading.LightSample;
import glint.shading.Lights;
import glint.shading.Materials;
import glint.shading.Optics;
import glint.shading.PathVertex;
import glint.shading.Phong;
import glint.shading.Rgb;
import glint.shading.ShadingContext;
import glint.shading.ShadingModel;
import glint.shading.Surface;

/**
 * One render thread's Whitted tracer: follows a ray to its nearest hit, describes the surface
 * there and lets the shading model send radiance back, tracing reflected and refracted rays by
 * recursion. Every ray asks the scene's one {@link Aggregate}, but a shadow ray the one chosen for
 * its light. Its scratch values live in one {@link PathVertex} a level, so nothing is allocated per
 * ray. All vectors are world space, directions unit length.
 */
final class Integrator implements ShadingContext {

    private static final ShadingModel COOK_TORRANCE = new CookTorrance();
    private static final ShadingModel PHONG = new Phong();

    private RenderScene scene;
    private Aggregate aggregate;
    /** Per light: the aggregate its shadow rays ask. */
    private Aggregate[] shadowAggregate;
    private Primitives primitives;
    private ShadingModel model;
    private TraversalStack stack;
    private PathVertex[] vertices = new PathVertex[0];
    /** Scratch: a camera ray's hit while a row's hits are found in the aggregate. */
    private final Hit cameraHit = new Hit();
    private final InsideWalk walk = new InsideWalk(this);

    // the scene's settings, read once per scene rather than through the record on every ray
    private double epsilon, minWeight;
    private boolean exactFresnel, roulette;
    private Materials materials;
    private Lights lights;

    /** Rays traced so far: camera, reflected, refracted and shadow rays. */
    private long rays;

    // the camera ray whose path is being traced, which seeds its random decisions, and how many it made
    private int pathPixel, pathFrame, pathSample, pathDraws;

    /** Makes this integrator trace rays of {@code renderScene}; cheap when it already does. */
    void prepare(RenderScene renderScene) {
        if (renderScene == scene) {
            return;
        }
        scene = renderScene;
        aggregate = renderScene.aggregate;
        shadowAggregate = renderScene.shadowAggregate;
        primitives = aggregate.primitives();
        RenderSettings settings = renderScene.settings;
        model = settings.shading() == Shading.PHONG ? PHONG : COOK_TORRANCE;
        epsilon = settings.epsilon();
        minWeight = settings.minWeight();
        exactFresnel = settings.glassFresnel() == RenderSettings.GlassFresnel.EXACT;
        roulette = settings.pruning() == RenderSettings.Pruning.ROULETTE;
        materials = renderScene.materials;
        lights = renderScene.lights;
        stack = aggregate.newStack();
        if (vertices.length <= settings.recursionMax()) {
            PathVertex[] grown = new PathVertex[settings.recursionMax() + 1];
            for (int i = 0; i < grown.length; i++) {
                grown[i] = i < vertices.length ? vertices[i] : new PathVertex();
            }
            vertices = grown;
        }
    }

    /**
     * Starts the path of camera ray (pixel, frame, sample): the roulette's random numbers that
     * follow are a pure function of these and of their order along the path, so the image does not
     * depend on threads or tiles.
     */
    void beginPath(int pixelIndex, int frameIndex, int sample) {
        pathPixel = pixelIndex;
        pathFrame = frameIndex;
        pathSample = sample;
        pathDraws = 0;
    }

    /**
     * What a child ray of path weight {@code childWeight} counts for: 1 when it is at least
     * min_weight (traced as it is, no number drawn); below, with roulette, 1 / q with probability
     * q = childWeight / min_weight (its weight becomes min_weight) and 0 otherwise, which keeps the
     * expected value; with the plain cut-off, 0. The caller traces the child with weight
     * {@code childWeight x keep} and scales its radiance by {@code keep} when that is above 0.
     */
    @Override
    public double keep(double childWeight) {
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
        rays++;
        if (!aggregate.nearest(ox, oy, oz, dx, dy, dz, Intersect.MISS, skip, inside, v.hit, stack)) {
            v.radiance.set(scene.backgroundR, scene.backgroundG, scene.backgroundB);
            return v.radiance;
        }
        return shadeHit(v, ox, oy, oz, dx, dy, dz, hitsLeft, weight);
    }

    /**
     * The nearest hits of camera rays r in [0, n) from o along (dx[r], dy[r], dz[r]), into
     * nearestT and nearestPrimitive ({@link Intersect#MISS} and {@link Hit#NONE} for none): among
     * {@code candidates}, gathered for the frustum the rays lie in, primitive by primitive
     * ({@link Candidates#nearestFromOrigin}), or where they are null, ray by ray in the aggregate.
     */
    void findCameraHits(Candidates candidates, double ox, double oy, double oz, double[] dx, double[] dy,
                        double[] dz, int n, double[] nearestT, int[] nearestPrimitive) {
        rays += n;
        if (candidates != null) {
            candidates.nearestFromOrigin(primitives, ox, oy, oz, dx, dy, dz, n, nearestT, nearestPrimitive);
            return;
        }
        Hit hit = cameraHit;
        for (int r = 0; r < n; r++) {
            boolean found = aggregate.nearest(ox, oy, oz, dx[r], dy[r], dz[r], Intersect.MISS, Hit.NONE, Hit.NONE, hit,
                    stack);
            nearestT[r] = found ? hit.t : Intersect.MISS;
            nearestPrimitive[r] = found ? hit.primitive : Hit.NONE;
        }
    }

    /**
     * {@link #trace} for a camera ray whose nearest hit is already known: primitive
     * {@code primitive} ({@link Hit#NONE} for none) at distance t.
     */
    Rgb shadeCamera(int primitive, double t, double ox, double oy, double oz, double dx, double dy, double dz,
                    int hitsLeft) {
        PathVertex v = vertices[hitsLeft];
        if (primitive == Hit.NONE) {
            v.radiance.set(scene.backgroundR, scene.backgroundG, scene.backgroundB);
            return v.radiance;
        }
        primitives.record(v.hit, primitive, t);
        return shadeHit(v, ox, oy, oz, dx, dy, dz, hitsLeft, 1);
    }

    /** Gathers into {@code out} the primitives the camera rays inside the frustum may meet. */
    void gather(Frustum frustum, Candidates out) {
        aggregate.gather(frustum, out, stack);
    }

    /** The radiance vertex v's hit (found by the unit ray from o along d) sends back along the ray. */
    private Rgb shadeHit(PathVertex v, double ox, double oy, double oz, double dx, double dy, double dz,
                         int hitsLeft, double weight) {
        Hit hit = v.hit;
        primitives.describe(hit, ox, oy, oz, dx, dy, dz);
        v.surface.set(hit, ox, oy, oz, dx, dy, dz, epsilon, scene.materialOf[hit.primitive],
                primitives.closed(hit.primitive));
        model.shade(this, v, dx, dy, dz, hitsLeft, weight);
        return v.radiance;
    }

    @Override
    public double lightReaching(Surface s, int i, LightSample out) {
        double cosine = lights.sample(i, s.px, s.py, s.pz, s.nx, s.ny, s.nz, out);
        if (!(cosine > 0)) { // NaN too: no light from an undefined direction
            return 0;
        }
        out.cosine = cosine;
        return transmittance(s, out, i);
    }

    /**
     * The fraction of light i, sampled as {@code light}, that reaches surface s: a shadow ray from s
     * towards the light, up to it, through the scene's shadow pass of each primitive it meets.
     */
    private double transmittance(Surface s, LightSample light, int i) {
        rays++;
        return shadowAggregate[i].transmittance(s.nearX(), s.nearY(), s.nearZ(), light.dirX, light.dirY, light.dirZ,
                light.distance, s.skipNear, scene.shadowPass, stack);
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

    @Override
    public void addReflected(Surface s, double dx, double dy, double dz, int hitsLeft, double weight, double fR,
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
     * Adds to {@code v.sum} what v's boundary (its factors from {@link ShadingModel#boundary})
     * reflects and refracts: the reflected ray through {@link #addReflected}, then the refracted one,
     * of path weight weight x the tint's largest channel, traced if {@link #keep} keeps it.
     */
    @Override
    public void scatter(PathVertex v, double dx, double dy, double dz, int hitsLeft, double weight) {
        if (hitsLeft <= 1) {
            return;
        }
        Rgb sum = v.sum;
        addReflected(v.surface, dx, dy, dz, hitsLeft, weight, v.reflect, v.reflect, v.reflect, sum);
        double childWeight = weight * Math.max(v.transmitR, Math.max(v.transmitG, v.transmitB));
        double keep = childWeight > 0 ? keep(childWeight) : 0;
        if (keep > 0) {
            Rgb refracted = traceRefracted(v, dx, dy, dz, hitsLeft, childWeight * keep);
            sum.r += keep * v.transmitR * refracted.r;
            sum.g += keep * v.transmitG * refracted.g;
            sum.b += keep * v.transmitB * refracted.b;
        }
    }

    /**
     * Traces the ray refracted through v's surface (eta = {@code v.eta}), its origin offset to the
     * far side; past the critical angle, the reflected one. Into a closed primitive nothing else
     * reaches into, the ray walks its inside ({@link InsideWalk}). Returns its radiance.
     */
    private Rgb traceRefracted(PathVertex v, double dx, double dy, double dz, int hitsLeft, double weight) {
        Surface s = v.surface;
        double[] t = v.refracted;
        if (!Optics.refract(dx, dy, dz, s.nx, s.ny, s.nz, s.cosIncident, v.eta, t)) {
            return traceReflected(s, dx, dy, dz, hitsLeft, weight);
        }
        if (s.insideFar != Hit.NONE && aggregate.emptyInside(s.insideFar)) {
            return walk.trace(s, t[0], t[1], t[2], hitsLeft - 1, weight);
        }
        return trace(s.farX(), s.farY(), s.farZ(), t[0], t[1], t[2], hitsLeft - 1, weight, s.skipFar, s.insideFar);
    }

    /** The scratch values of recursion level {@code hitsLeft}. */
    PathVertex vertex(int hitsLeft) {
        return vertices[hitsLeft];
    }

    ShadingModel model() {
        return model;
    }

    Primitives primitives() {
        return primitives;
    }

    /** Per primitive: its material's number. */
    int materialOf(int primitive) {
        return scene.materialOf[primitive];
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

    @Override
    public boolean exactFresnel() {
        return exactFresnel;
    }

    /** How far rays leaving a surface start off it, per unit of max(1, |p|). */
    double epsilon() {
        return epsilon;
    }

    /** Rays traced so far: camera, reflected, refracted and shadow rays. */
    long rays() {
        return rays;
    }

    /** Counts a ray whose hit was found without a search (a chord inside a closed primitive). */
    void countRay() {
        rays++;
    }
}
