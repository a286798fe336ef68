package glint.render;

import glint.shading.LightSample;
import glint.shading.Lights;
import glint.shading.Rgb;
import glint.shading.Surface;

/**
 * One render thread's bidirectional path tracer (docs/conventions.md, "Light from both ends"; Veach
 * 1997, chapter 10): a pass first traces its light subpaths, one every two pixels, each from a light
 * chosen by its power ({@link #traceLightPaths}), then for each pixel a subpath from the camera
 * ({@link #shadeCamera}), each a random walk as the path integrator's ({@link BdptSubpaths}); pixel p's
 * joins light subpath p (modulo their count) every way, strategy (s, t) taking the light subpath's first
 * s vertices and the camera's first t:
 * <ul>
 * <li>s = 0: the camera subpath itself, where it meets a light's body or escapes to light at infinity;
 * <li>s = 1: a camera vertex joined to a point sampled on every light, as the path integrator's
 * next-event estimation;
 * <li>t = 1: a light vertex joined to a point of the camera's lens, its light added at the pixel the
 * camera sees it at ({@link Splats}: light tracing), as the light subpath is traced;
 * <li>otherwise: the two subpaths' last vertices joined by a shadow ray;
 * <li>and, where the frame merges ({@link #pass}), each camera vertex on a diffuse surface merged with
 * the points of the pass's other light subpaths within the merge radius ({@link LightVertices}; vertex
 * merging, Georgiev et al. 2012): what makes light focused by glass and seen through glass.
 * </ul>
 * Each strategy's light is weighed by the power heuristic over every strategy, join or merge, that could
 * have made the same path ({@link BdptWeights}), so together they count it once. A path has at most
 * {@code recursion_max} surface hits, and each subpath ends by Russian roulette as the path
 * integrator's. Allocates nothing per path.
 */
final class BdptIntegrator extends Integrator {

    /** Random dimensions of the light subpath: which light, its ray (two pairs), its target, then 3 a vertex. */
    private static final int LIGHT_PATH = 1 << 22;
    /** Random dimensions of the light samples of s = 1: a pair for each light at each camera vertex. */
    private static final int LIGHT_SAMPLE = 2 << 22;
    /** Random dimensions of the lens points of t = 1, one pair for each light vertex. */
    private static final int LENS_SAMPLE = 3 << 22;

    /**
     * The light subpaths a pass traces for camera paths to join and merge with: one every this many pixels
     * (Georgiev et al. 2012 trace one a pixel). Measured at 200 x 150 against one a pixel: render CPU a frame
     * 0.66 to 0.80 (CompareBuilds, 4 pairs: caustics, caustic-lamp, lamp-and-frost, default, metals); at the
     * same samples, caustic-lamp's relMSE against its reference within 1.5 % at 16, 64 and 256 samples and
     * its FLIP 1 to 6 % lower (BdptStudy). At 4 and 8 pixels a subpath, caustic-lamp's relMSE at 64 samples
     * grew 1.1 and 1.3 times.
     */
    static final int PIXELS_PER_LIGHT_PATH = 2;
    /** The most light subpaths a pass traces, which bounds the memory they take (about 45 MB). */
    static final int MOST_LIGHT_PATHS = 1 << 16;
    /**
     * The merge radius of the first pass, in pixel widths at the scene's centre, so that a merge blurs
     * the same at any image size. Measured on caustic-lamp at 200 x 150 and 64 samples against its
     * reference: relMSE 1.56e-2 at 0.75 pixel widths, 1.08e-2 at 1.5 and 1.22e-2 at 3; FLIP 0.050, 0.049
     * and 0.072 (the caustic blurred).
     */
    static final double MERGE_PIXELS = 1.5;
    /**
     * The most the first pass's merge radius may be, over the radius of the sphere around the scene and
     * the camera: in an image of a few pixels, 1.5 of them would blur light across whole objects (on a
     * 16 x 12 white furnace the image came out too bright); at 100 x 75 and above it binds on none of the
     * reference scenes nor on the default, metals and caustics scenes.
     */
    static final double MOST_MERGE_RADIUS = 0.02;
    /**
     * How fast the merge radius shrinks with the passes, r_n = r_1 n^((alpha - 1) / 2): the bias goes
     * and the variance grows in the proportion that makes the error fall fastest (Knaus and Zwicker 2011).
     */
    static final double MERGE_ALPHA = 0.75;

    /** The light subpaths each pass traces for a frame of {@code pixels}. */
    static int lightPaths(int pixels) {
        return Math.min((pixels + PIXELS_PER_LIGHT_PATH - 1) / PIXELS_PER_LIGHT_PATH, MOST_LIGHT_PATHS);
    }

    /**
     * The merge radius of the first pass where a pixel is {@code pixelWidth} wide at the scene's centre and
     * the scene's sphere has radius {@code sceneRadius}.
     */
    static double firstMergeRadius(double pixelWidth, double sceneRadius) {
        return Math.min(MERGE_PIXELS * pixelWidth, MOST_MERGE_RADIUS * sceneRadius);
    }

    /** The merge radius of pass {@code pass} (0, 1, ...) where the first pass's is {@code first}. */
    static double mergeRadius(double first, long pass) {
        return first * Math.pow(pass + 1, (MERGE_ALPHA - 1) / 2);
    }

    private final PathSamples random = new PathSamples();
    private final BdptSubpaths subpaths = new BdptSubpaths(this, random);
    private final LightSample lightSample = new LightSample();
    private final CameraSight sight = new CameraSight();
    private final Rgb f = new Rgb();
    private final Rgb f2 = new Rgb();
    private final Rgb radiance = new Rgb();
    /** The scene's lights and sky, what they are chosen by, and the sphere their far light crosses. */
    final BdptWeights weights = new BdptWeights();
    private Splats splats;
    private int width, height;
    BdptVertex[] camera = new BdptVertex[0], light = new BdptVertex[0];
    /** How many vertices the last camera ray's subpaths had: what tests read its vertices by. */
    int cameraVertices, lightVertices;
    /**
     * The light subpaths of the pass: each camera path joins one of them, and merges with all of them
     * within their radius where that is not 0.
     */
    private LightVertices traced;
    /** The pixel whose camera path is being traced: the light subpath it joins is that one of the pass's. */
    private int pixel;
    /** Each merge's light over the paths merged with times the area of the merge disc. */
    private double mergeScale;
    /** A light subpath merged with, loaded, and the grid's buckets near a camera vertex. */
    private BdptVertex[] mergedPath = new BdptVertex[0];
    private final int[] near = new int[8];
    /** The vertices of s = 1 and t = 1, which the strategy samples in place of the subpath's first. */
    private final BdptVertex sampledLight = new BdptVertex(), sampledCamera = new BdptVertex();

    @Override
    void prepared(RenderSettings settings) {
        int vertices = settings.recursionMax() + 2;
        if (camera.length != vertices) {
            camera = vertices(vertices);
            light = vertices(vertices);
            mergedPath = vertices(vertices);
        }
        weights.prepare(scene, this);
    }

    private static BdptVertex[] vertices(int n) {
        BdptVertex[] v = new BdptVertex[n];
        for (int i = 0; i < n; i++) {
            v[i] = new BdptVertex();
        }
        return v;
    }

    /** Where light tracing adds its light: the frame's splats, of its size. */
    void splatInto(Splats frameSplats) {
        splats = frameSplats;
        width = frameSplats.width();
        height = frameSplats.height();
        weights.film(width, height);
    }

    /**
     * The pass's light subpaths, from now on: traced into {@code vertices} ({@link #traceLightPaths}), and
     * once it is finished, joined by camera paths, which merge with them within their radius where that
     * is not 0 (vertex merging). The frame's splats are set ({@link #splatInto}).
     */
    void pass(LightVertices vertices) {
        traced = vertices;
        double r = vertices.radius();
        int paths = vertices.paths();
        weights.merging(r > 0 ? paths : 0, r);
        weights.lightTracing((double) paths / ((double) width * height));
        mergeScale = r > 0 ? 1 / (paths * Math.PI * r * r) : 0;
    }

    /**
     * Traces light subpaths [first, first + count) of pass (frame, sample) of {@code samples} into
     * {@code chunk}, for camera paths to join and merge with, with {@code hitsLeft} surface hits as a camera
     * ray's, and adds each one's light tracing (t = 1) to the splats: light subpath p uses pixel p's
     * random numbers, and is the one pixel p's camera path joins.
     */
    void traceLightPaths(LightVertices.Chunk chunk, int first, int count, int frameIndex, int sample, int samples,
                         int hitsLeft) {
        chunk.clear();
        for (int p = first; p < first + count; p++) {
            random.begin(p, frameIndex, sample, samples);
            int n = subpaths.lightSubpath(light, hitsLeft + 1, LIGHT_PATH);
            chunk.add(light, n);
            for (int s = 2; s <= n && s - 1 <= hitsLeft; s++) {
                if (weights.chosen(s, 1)) {
                    splat(s);
                }
            }
        }
    }

    @Override
    void beginPath(int pixelIndex, int frameIndex, int sample, int samples) {
        random.begin(pixelIndex, frameIndex, sample, samples);
        pixel = pixelIndex;
    }

    @Override
    PathSamples lightNumbers(int i) {
        return random; // the light samples of s = 1 draw their own dimensions
    }

    @Override
    Rgb shadeCamera(int primitive, double t, double ox, double oy, double oz, double dx, double dy, double dz,
                    int hitsLeft) {
        BdptVertex eye = camera[0];
        eye.kind = BdptVertex.CAMERA;
        eye.setPoint(ox, oy, oz);
        eye.setNormal(0, 0, 0);
        eye.setBeta(1, 1, 1);
        eye.delta = false;
        eye.connectible = true;
        double pdfDirection = scene.camera.directionPdf(ox, oy, oz, dx, dy, dz, width, height);
        cameraVertices = subpaths.cameraSubpath(camera, hitsLeft + 2, ox, oy, oz, dx, dy, dz, pdfDirection,
                primitive, t);
        lightVertices = traced.loadPathNumber(pixel % traced.paths(), light);
        double r = 0, g = 0, b = 0;
        for (int tv = 2; tv <= cameraVertices; tv++) { // tv = 1, light tracing, is the light subpath's own
            for (int s = 0; s <= lightVertices && s + tv - 2 <= hitsLeft; s++) {
                if (!weights.chosen(s, tv)) {
                    continue;
                }
                if (s == 1) {
                    lightSampled(camera[tv - 1], tv);
                    r += radiance.r;
                    g += radiance.g;
                    b += radiance.b;
                } else if (connect(s, tv)) {
                    r += radiance.r;
                    g += radiance.g;
                    b += radiance.b;
                }
            }
        }
        if (traced.radius() > 0 && weights.mergesChosen()) {
            for (int tv = 2; tv <= cameraVertices; tv++) {
                merge(tv, hitsLeft);
                r += f2.r;
                g += f2.g;
                b += f2.b;
            }
        }
        radiance.set(r, g, b);
        if (!Double.isFinite(r + g + b)) { // counted as black
            radiance.set(0, 0, 0);
        }
        return radiance;
    }

    // ---------------------------------------------------------------- the strategies

    /**
     * Strategy (s, t) for t >= 2, its weighted light into {@link #radiance}; false where it brings none.
     */
    private boolean connect(int s, int t) {
        BdptVertex pt = camera[t - 1];
        if (s == 0) {
            return emitted(pt, t);
        }
        if (!pt.connectible) {
            return false;
        }
        BdptVertex qs = light[s - 1];
        if (!qs.connectible) {
            return false;
        }
        Surface a = pt.surface, b = qs.surface;
        double wx = b.px - a.px, wy = b.py - a.py, wz = b.pz - a.pz;
        double distance2 = wx * wx + wy * wy + wz * wz;
        double inv = 1 / Math.sqrt(distance2);
        wx *= inv;
        wy *= inv;
        wz *= inv;
        weights.evaluate(pt, pt.woX, pt.woY, pt.woZ, wx, wy, wz, f);
        if (f.r == 0 && f.g == 0 && f.b == 0) {
            return false;
        }
        weights.evaluate(qs, -wx, -wy, -wz, qs.woX, qs.woY, qs.woZ, f2);
        if (f2.r == 0 && f2.g == 0 && f2.b == 0) {
            return false;
        }
        double g = Math.abs(a.nx * wx + a.ny * wy + a.nz * wz) * Math.abs(b.nx * wx + b.ny * wy + b.nz * wz)
                * inv * inv;
        double visible = visibleBetween(pt, qs);
        if (visible == 0) {
            return false;
        }
        double k = g * visible * weights.weight(s, t, camera, light, sampledLight, sampledCamera);
        radiance.set(pt.betaR * f.r * f2.r * qs.betaR * k, pt.betaG * f.g * f2.g * qs.betaG * k,
                pt.betaB * f.b * f2.b * qs.betaB * k);
        return true;
    }

    /** s = 0: the light of the body or of the light at infinity the camera subpath ends at, weighted. */
    private boolean emitted(BdptVertex pt, int t) {
        if (pt.kind == BdptVertex.LIGHT) {
            materials.bsdf(pt.surface.material).emitted(materials, pt.surface, f);
        } else if (pt.kind == BdptVertex.FAR) {
            escaped(pt.farX, pt.farY, pt.farZ, f2, f); // the sky and every sun's disc
        } else {
            return false;
        }
        if (f.r == 0 && f.g == 0 && f.b == 0) {
            return false;
        }
        double w = weights.weight(0, t, camera, light, sampledLight, sampledCamera);
        radiance.set(pt.betaR * f.r * w, pt.betaG * f.g * w, pt.betaB * f.b * w);
        return true;
    }

    /**
     * s = 1: camera vertex pt joined to a point sampled on each light and on the sky, each weighted, summed
     * into {@link #radiance} (0 where pt cannot be joined).
     */
    private void lightSampled(BdptVertex pt, int t) {
        double r = 0, g = 0, b = 0;
        if (pt.connectible) {
            Lights all = scene.lightsAndSky;
            for (int k = 0, n = all.count(); k < n; k++) {
                if (lightSampled(pt, t, k)) {
                    r += f2.r;
                    g += f2.g;
                    b += f2.b;
                }
            }
        }
        radiance.set(r, g, b);
    }

    /**
     * Camera vertex pt joined to a point of light k sampled as seen from pt (from its far side where the
     * light is behind a surface that lets light through), its weighted light into {@link #f2}.
     */
    private boolean lightSampled(BdptVertex pt, int t, int k) {
        Lights all = scene.lightsAndSky;
        random.pair(LIGHT_SAMPLE + (t - 1) * all.count() + k);
        Surface s = pt.surface;
        LightSample ls = lightSample;
        double visible = lightReaching(all, k < lights.count() ? shadowAggregateOf(k) : aggregate, s, k, random.u1,
                random.u2, weights.transmits(s.material), ls);
        if (visible == 0) {
            return false;
        }
        weights.evaluate(pt, pt.woX, pt.woY, pt.woZ, ls.dirX, ls.dirY, ls.dirZ, f);
        if (f.r == 0 && f.g == 0 && f.b == 0) {
            return false;
        }
        boolean near = ls.dirX * s.nx + ls.dirY * s.ny + ls.dirZ * s.nz > 0;
        weights.lightVertex(k, s, near, ls, sampledLight);
        double w = weights.weight(1, t, camera, light, sampledLight, sampledCamera);
        double kk = ls.cosine * visible * w;
        f2.set(pt.betaR * f.r * ls.irradianceR * kk, pt.betaG * f.g * ls.irradianceG * kk,
                pt.betaB * f.b * ls.irradianceB * kk);
        return true;
    }

    /**
     * t = 1: light vertex qs (s >= 2) joined to a point of the camera's lens; its weighted light added at
     * the pixel the camera sees qs at.
     */
    private void splat(int s) {
        BdptVertex qs = light[s - 1];
        if (!qs.connectible || splats == null) {
            return;
        }
        Surface b = qs.surface;
        random.pair(LENS_SAMPLE + s - 1);
        CameraSight c = sight;
        if (!scene.camera.sees(b.px, b.py, b.pz, random.u1, random.u2, width, height, c)) {
            return;
        }
        weights.evaluate(qs, c.towardX, c.towardY, c.towardZ, qs.woX, qs.woY, qs.woZ, f);
        if (f.r == 0 && f.g == 0 && f.b == 0) {
            return;
        }
        double cos = Math.abs(b.nx * c.towardX + b.ny * c.towardY + b.nz * c.towardZ);
        double visible = visibleFrom(qs, c.towardX, c.towardY, c.towardZ, c.distance);
        if (visible == 0) {
            return;
        }
        BdptVertex eye = sampledCamera;
        eye.kind = BdptVertex.CAMERA;
        eye.setPoint(c.lensX, c.lensY, c.lensZ);
        eye.setNormal(0, 0, 0);
        eye.delta = false;
        eye.connectible = true;
        double k = cos / (c.distance * c.distance) * c.importance * visible
                * weights.weight(s, 1, camera, light, sampledLight, sampledCamera);
        splats.add((int) c.filmX, (int) c.filmY, qs.betaR * f.r * k, qs.betaG * f.g * k, qs.betaB * f.b * k);
    }

    /**
     * Vertex merging at camera vertex camera[tv - 1]: the light of every vertex of the pass's light subpaths
     * within the merge radius, as if it lay on the camera vertex, each weighted, summed into {@link #f2}.
     */
    private void merge(int tv, int hitsLeft) {
        double r = 0, g = 0, b = 0;
        BdptVertex pt = camera[tv - 1];
        if (pt.kind == BdptVertex.SURFACE && pt.diffuse) {
            Surface a = pt.surface;
            LightVertices lv = traced;
            double radius2 = lv.radius() * lv.radius();
            for (int k = 0, n = lv.bucketsNear(a.px, a.py, a.pz, near); k < n; k++) {
                for (int i = lv.bucketFrom(near[k]), end = lv.bucketTo(near[k]); i < end; i++) {
                    if (lv.distance2At(i, a.px, a.py, a.pz) >= radius2) {
                        continue;
                    }
                    int v = lv.vertexAt(i);
                    int s = lv.indexOnPath(v) + 1;
                    if (s + tv - 3 > hitsLeft) {
                        continue;
                    }
                    lv.loadPath(v, mergedPath);
                    BdptVertex y = mergedPath[s - 1];
                    weights.evaluate(pt, pt.woX, pt.woY, pt.woZ, y.woX, y.woY, y.woZ, f);
                    if (f.r == 0 && f.g == 0 && f.b == 0) {
                        continue;
                    }
                    double k2 = weights.mergeWeight(s, tv, camera, mergedPath) * mergeScale;
                    r += pt.betaR * f.r * y.betaR * k2;
                    g += pt.betaG * f.g * y.betaG * k2;
                    b += pt.betaB * f.b * y.betaB * k2;
                }
            }
        }
        f2.set(r, g, b);
    }

    // ---------------------------------------------------------------- shadow rays

    /**
     * The fraction of light passing between surface vertices a and b: along the ray from a's offset point on
     * b's side to b's offset point on a's side, stopped {@link #SHORT_OF_LIGHT} short of it, so that
     * neither surface shadows its own point.
     */
    private double visibleBetween(BdptVertex a, BdptVertex b) {
        Surface s = a.surface, e = b.surface;
        double vx = e.px - s.px, vy = e.py - s.py, vz = e.pz - s.pz;
        boolean near = vx * s.nx + vy * s.ny + vz * s.nz > 0; // b lies on the side a's normal faces
        boolean endNear = vx * e.nx + vy * e.ny + vz * e.nz < 0; // a lies on the side b's normal faces
        double ox = near ? s.nearX() : s.farX(), oy = near ? s.nearY() : s.farY(), oz = near ? s.nearZ() : s.farZ();
        double dx = (endNear ? e.nearX() : e.farX()) - ox, dy = (endNear ? e.nearY() : e.farY()) - oy;
        double dz = (endNear ? e.nearZ() : e.farZ()) - oz;
        double distance = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double inv = 1 / distance;
        return transmittance(aggregate, ox, oy, oz, dx * inv, dy * inv, dz * inv, distance * (1 - SHORT_OF_LIGHT),
                near ? s.skipNear : s.skipFar);
    }

    /** The fraction of light passing from surface vertex v along unit w for {@code distance}, to a point on no surface. */
    private double visibleFrom(BdptVertex v, double wx, double wy, double wz, double distance) {
        Surface s = v.surface;
        boolean near = wx * s.nx + wy * s.ny + wz * s.nz > 0;
        return near ? transmittance(aggregate, s.nearX(), s.nearY(), s.nearZ(), wx, wy, wz, distance, s.skipNear)
                : transmittance(aggregate, s.farX(), s.farY(), s.farZ(), wx, wy, wz, distance, s.skipFar);
    }
}
