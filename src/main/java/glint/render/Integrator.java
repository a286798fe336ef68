package glint.render;

import glint.accel.Aggregate;
import glint.accel.Candidates;
import glint.accel.Frustum;
import glint.accel.TraversalStack;
import glint.geometry.Hit;
import glint.geometry.Intersect;
import glint.geometry.Primitives;
import glint.shading.LightQuery;
import glint.shading.LightSample;
import glint.shading.Lights;
import glint.shading.Materials;
import glint.shading.Rgb;
import glint.shading.Surface;

/**
 * One render thread's light transport: what it shares whatever the method, the rays. Every ray
 * asks the scene's one {@link Aggregate} ({@link #nearest}), but a shadow ray the one chosen for its
 * light ({@link #lightReaching}); a row's camera rays are searched together ({@link #findCameraHits}).
 * {@link WhittedIntegrator} and {@link PathIntegrator} say what the rays bring back. All vectors are
 * world space, directions unit length.
 */
abstract class Integrator implements LightQuery {

    RenderScene scene;
    Aggregate aggregate;
    /** Per light: the aggregate its shadow rays ask. */
    private Aggregate[] shadowAggregate;
    Primitives primitives;
    TraversalStack stack;
    /** Scratch: a camera ray's hit while a row's hits are found in the aggregate. */
    private final Hit cameraHit = new Hit();

    // the scene's settings, read once per scene rather than through the record on every ray
    double epsilon;
    Materials materials;
    Lights lights;

    /** Rays traced so far: camera, reflected, refracted and shadow rays. */
    private long rays;

    /**
     * How much shorter than the distance to a light with a size its shadow ray is, relative: far
     * above the error of the distance worked out to the point sampled against the sphere test's
     * (3e-14 relative at worst over 10^5 samples of a sphere light, grazing ones too), far below any
     * gap a scene could mean.
     */
    static final double SHORT_OF_LIGHT = 1e-9;

    /** Makes this integrator trace rays of {@code renderScene}; cheap when it already does. */
    final void prepare(RenderScene renderScene) {
        if (renderScene == scene) {
            return;
        }
        scene = renderScene;
        aggregate = renderScene.aggregate;
        shadowAggregate = renderScene.shadowAggregate;
        primitives = aggregate.primitives();
        epsilon = renderScene.settings.epsilon();
        materials = renderScene.materials;
        lights = renderScene.lights;
        stack = aggregate.newStack();
        prepared(renderScene.settings);
    }

    /** Reads what the method needs of the settings of the scene just prepared. */
    abstract void prepared(RenderSettings settings);

    /**
     * Starts the path of camera ray (pixel, frame, sample) of a pixel's {@code samples}: the random
     * numbers that follow are a pure function of these and of their order along the path, so the
     * image does not depend on threads or tiles.
     */
    abstract void beginPath(int pixelIndex, int frameIndex, int sample, int samples);

    /**
     * The radiance a camera ray from o along d brings back, its nearest hit already known: primitive
     * {@code primitive} ({@link Hit#NONE} for none) at distance t, with {@code hitsLeft} surface hits
     * to shade. A scratch value: read it before the next ray.
     */
    abstract Rgb shadeCamera(int primitive, double t, double ox, double oy, double oz, double dx, double dy,
                             double dz, int hitsLeft);

    /**
     * The nearest hits of camera rays r in [0, n) from o along (dx[r], dy[r], dz[r]), into
     * nearestT and nearestPrimitive ({@link Intersect#MISS} and {@link Hit#NONE} for none): among
     * {@code candidates}, gathered for the frustum the rays lie in, primitive by primitive
     * ({@link Candidates#nearestFromOrigin}), or where they are null, ray by ray in the aggregate.
     */
    final void findCameraHits(Candidates candidates, double ox, double oy, double oz, double[] dx, double[] dy,
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
     * The nearest hits of camera rays r in [0, n), each from its own origin (ox[r], oy[r], oz[r]) along
     * (dx[r], dy[r], dz[r]), found ray by ray in the aggregate, into nearestT and nearestPrimitive
     * ({@link Intersect#MISS} and {@link Hit#NONE} for none): the rays of a lens.
     */
    final void findCameraHits(double[] ox, double[] oy, double[] oz, double[] dx, double[] dy, double[] dz, int n,
                              double[] nearestT, int[] nearestPrimitive) {
        rays += n;
        Hit hit = cameraHit;
        for (int r = 0; r < n; r++) {
            boolean found = aggregate.nearest(ox[r], oy[r], oz[r], dx[r], dy[r], dz[r], Intersect.MISS, Hit.NONE,
                    Hit.NONE, hit, stack);
            nearestT[r] = found ? hit.t : Intersect.MISS;
            nearestPrimitive[r] = found ? hit.primitive : Hit.NONE;
        }
    }

    /** Gathers into {@code out} the primitives the camera rays inside the frustum may meet. */
    final void gather(Frustum frustum, Candidates out) {
        aggregate.gather(frustum, out, stack);
    }

    /**
     * The nearest hit of the ray from o along d into {@code hit}; false where it escapes. {@code skip}
     * is the primitive it leaves on its outer side, {@code inside} the closed one it travels inside of.
     */
    final boolean nearest(double ox, double oy, double oz, double dx, double dy, double dz, int skip, int inside,
                          Hit hit) {
        rays++;
        return aggregate.nearest(ox, oy, oz, dx, dy, dz, Intersect.MISS, skip, inside, hit, stack);
    }

    /** Fills surface s for the ray from o along d that met {@code hit}: the point, the facing normal, the offsets. */
    final void describe(Hit hit, double ox, double oy, double oz, double dx, double dy, double dz, Surface s) {
        primitives.describe(hit, ox, oy, oz, dx, dy, dz);
        s.set(hit, ox, oy, oz, dx, dy, dz, epsilon, scene.materialOf[hit.primitive], primitives.closed(hit.primitive));
    }

    /**
     * Light i seen from surface s, into {@code out} (with {@code out.cosine} = |n.l|): the fraction of
     * it that reaches s, through the shadow pass of whatever its shadow ray meets; 0 where it is
     * blocked, and where it is behind the surface unless {@code through}, when the shadow ray leaves
     * from the far side. A light with a size is sampled by the numbers {@link #lightNumbers} draws for
     * it, seen from the shadow ray's origin, so that the ray's length is the distance to the light.
     */
    @Override
    public final double lightReaching(Surface s, int i, boolean through, LightSample out) {
        double u1 = 0, u2 = 0;
        if (!lights.isDelta(i)) {
            PathSamples numbers = lightNumbers(i);
            u1 = numbers.u1;
            u2 = numbers.u2;
        }
        return lightReaching(lights, shadowAggregate[i], s, i, u1, u2, through, out);
    }

    /**
     * Light i of {@code from}, sampled by u1 and u2 (ignored by a delta light), seen from surface s, into
     * {@code out}: {@link #lightReaching(Surface, int, boolean, LightSample)} for any list of lights, its shadow
     * ray searched in {@code searched}.
     */
    final double lightReaching(Lights from, Aggregate searched, Surface s, int i, double u1, double u2,
                               boolean through, LightSample out) {
        boolean delta = from.isDelta(i);
        boolean found = delta ? from.sample(i, s.px, s.py, s.pz, 0, 0, out)
                : from.sample(i, s.nearX(), s.nearY(), s.nearZ(), u1, u2, out);
        double cosine = found ? out.dirX * s.nx + out.dirY * s.ny + out.dirZ * s.nz : 0;
        if (cosine > 0) {
            out.cosine = cosine;
            return transmittance(s, out, searched, delta, true);
        }
        if (!through || !(cosine < 0)) { // NaN too: no light from an undefined direction
            return 0;
        }
        if (!delta && !from.sample(i, s.farX(), s.farY(), s.farZ(), u1, u2, out)) {
            return 0;
        }
        cosine = out.dirX * s.nx + out.dirY * s.ny + out.dirZ * s.nz;
        if (!(cosine < 0)) {
            return 0;
        }
        out.cosine = -cosine;
        return transmittance(s, out, searched, delta, false);
    }

    /**
     * The pair of numbers that samples light i at the surface being lit, in {@code u1} and {@code u2}
     * of what it returns: each integrator says which of its dimensions they are.
     */
    abstract PathSamples lightNumbers(int light);

    /**
     * The fraction of a light, sampled as {@code light}, that reaches surface s: a shadow ray from s (from its
     * {@code near} side, or its far one) towards the light, up to it, searched in {@code searched} through the
     * scene's shadow pass of each primitive it meets. A ray towards a light with a size (not {@code delta};
     * sampled from the ray's origin) stops short of the point sampled on it by {@link #SHORT_OF_LIGHT} of its
     * length, so that the light's own body never shadows it.
     */
    private double transmittance(Surface s, LightSample light, Aggregate searched, boolean delta, boolean near) {
        double tMax = light.distance;
        if (!delta && tMax < Double.POSITIVE_INFINITY) {
            tMax *= 1 - SHORT_OF_LIGHT;
        }
        return near ? transmittance(searched, s.nearX(), s.nearY(), s.nearZ(), light.dirX, light.dirY, light.dirZ,
                tMax, s.skipNear) : transmittance(searched, s.farX(), s.farY(), s.farZ(), light.dirX, light.dirY,
                light.dirZ, tMax, s.skipFar);
    }

    /**
     * The fraction of light that passes along the shadow ray from o along unit d before tMax, searched
     * in {@code through}, leaving primitive {@code skip} behind.
     */
    final double transmittance(Aggregate through, double ox, double oy, double oz, double dx, double dy, double dz,
                               double tMax, int skip) {
        rays++;
        return through.transmittance(ox, oy, oz, dx, dy, dz, tMax, skip, scene.shadowPass, stack);
    }

    /** The aggregate light i's shadow rays ask. */
    final Aggregate shadowAggregateOf(int i) {
        return shadowAggregate[i];
    }

    /**
     * The radiance a ray escaping the scene along unit direction d brings: the background, and every
     * light at infinity seen along d (a sun's disc), into {@code out}; {@code scratch} is a scratch value.
     */
    final void escaped(double dx, double dy, double dz, Rgb scratch, Rgb out) {
        double r = scene.backgroundR, g = scene.backgroundG, b = scene.backgroundB;
        for (int k = 0, n = lights.countAtInfinity(); k < n; k++) {
            lights.arriving(lights.atInfinity(k), dx, dy, dz, scratch);
            r += scratch.r;
            g += scratch.g;
            b += scratch.b;
        }
        out.set(r, g, b);
    }

    Primitives primitives() {
        return primitives;
    }

    /** Per primitive: its material's number. */
    int materialOf(int primitive) {
        return scene.materialOf[primitive];
    }

    /** How far rays leaving a surface start off it, per unit of max(1, |p|). */
    double epsilon() {
        return epsilon;
    }

    /** Rays traced so far: camera, reflected, refracted and shadow rays. */
    final long rays() {
        return rays;
    }

    /** Counts a ray whose hit was found without a search (a chord inside a closed primitive). */
    final void countRay() {
        rays++;
    }
}
