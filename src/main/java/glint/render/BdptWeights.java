package glint.render;

import glint.shading.Bsdf;
import glint.shading.LightRay;
import glint.shading.LightSample;
import glint.shading.LightTargets;
import glint.shading.Lights;
import glint.shading.Materials;
import glint.shading.Rgb;
import glint.shading.Surface;

/**
 * What a bidirectional path is weighed by ({@link BdptIntegrator}): the densities with which either end
 * reaches a vertex, and the multiple importance sampling weight of a strategy: the power heuristic over
 * every strategy that makes the same path, worked out as a chain of density ratios along it (Veach 1997,
 * 10.2; pbrt's BDPT computes it the same way). Where light subpaths start, and how much denser next-event
 * estimation makes a path's light end, is {@link LightChoice}'s. A strategy the integrator has not got (a
 * light point seen by the camera directly, s = t = 1; a light path ending on the lens, t = 0) never
 * counts. One per render thread.
 */
final class BdptWeights {

    /**
     * The densities recorded on either side of a delta vertex (one a specular chain passes through): 1,
     * so that they cancel in every ratio, none of the strategies joining the path there. The chain's
     * two ends carry its densities instead ({@link #throughChain}). (Any other density of 0 means a
     * strategy that cannot make the path.)
     */
    static final double PAST_DELTA = 1;

    /** Which light a light subpath starts from, and the sphere around the scene. */
    final LightChoice choice = new LightChoice();

    private RenderScene scene;
    private Lights lights;
    private Materials materials;
    /** What light subpaths from a light with a position aim at ({@link LightTargets}). */
    LightTargets targets = LightTargets.none();
    private int width, height;
    /** The strategy a test or study renders alone, and whether weighted; -1: every strategy. */
    private int onlyS = -1, onlyT = -1;
    private boolean weighted = true;

    /**
     * Vertex merging's factor (Georgiev et al. 2012): the light subpaths merged with, times the area of the
     * merge disc; 0 without merging.
     */
    private double eta;
    /** The light subpaths a pass traces over its camera paths: how much denser light tracing is than 1 a path. */
    private double lightTracing = 1;

    private final LightRay leaving = new LightRay();
    private final Surface turned = new Surface();
    private final double[] w = new double[3];

    /** Reads what the weights need of a scene being prepared for {@code integrator}. */
    void prepare(RenderScene renderScene, Integrator integrator) {
        scene = renderScene;
        lights = renderScene.lightsAndSky;
        materials = renderScene.materials;
        targets = renderScene.lightTargets;
        onlyS = renderScene.strategyS;
        onlyT = renderScene.strategyT;
        weighted = renderScene.strategyWeighted;
        choice.prepare(renderScene);
    }

    /** Merging with {@code paths} light subpaths within {@code radius}; 0 paths: none. */
    void merging(int paths, double radius) {
        eta = paths * Math.PI * radius * radius;
    }

    /**
     * Light tracing (t = 1) from {@code share} light subpaths a camera path (fewer than one where a frame
     * has more pixels than a pass traces light subpaths): its density counts that many times.
     */
    void lightTracing(double share) {
        lightTracing = share;
    }

    /** The image size the camera's densities are of. */
    void film(int frameWidth, int frameHeight) {
        width = frameWidth;
        height = frameHeight;
    }

    /** Whether strategy (s, t) is rendered: all are, unless the scene asks for one alone. */
    boolean chosen(int s, int t) {
        return onlyS == -1 || s == onlyS && t == onlyT;
    }

    /** Whether merges are rendered: they are, unless the scene asks for one join alone. */
    boolean mergesChosen() {
        return onlyS == -1 || onlyS == RenderScene.MERGES;
    }

    // ---------------------------------------------------------------- BSDFs from either side

    /**
     * f(wo, wi) at surface vertex v, into {@code out}: wo and wi anywhere on the sphere, the surface met
     * from wo's side.
     */
    void evaluate(BdptVertex v, double woX, double woY, double woZ, double wiX, double wiY, double wiZ, Rgb out) {
        Surface s = facing(v.surface, woX, woY, woZ);
        materials.bsdf(s.material).evaluate(materials, s, woX, woY, woZ, wiX, wiY, wiZ, out);
    }

    /** The density with which surface vertex v's BSDF samples wi given wo, the surface met from wo's side. */
    double bsdfPdf(BdptVertex v, double woX, double woY, double woZ, double wiX, double wiY, double wiZ) {
        Surface s = facing(v.surface, woX, woY, woZ);
        return materials.bsdf(s.material).pdf(materials, s, woX, woY, woZ, wiX, wiY, wiZ);
    }

    /** s itself where its normal faces w, else a copy met from the other side. */
    private Surface facing(Surface s, double wx, double wy, double wz) {
        double cos = wx * s.nx + wy * s.ny + wz * s.nz;
        if (cos >= 0) {
            return s;
        }
        Surface t = turned;
        t.px = s.px;
        t.py = s.py;
        t.pz = s.pz;
        t.nx = -s.nx;
        t.ny = -s.ny;
        t.nz = -s.nz;
        t.front = !s.front;
        t.cosIncident = -cos;
        t.material = s.material;
        return t;
    }

    /**
     * The factor that turns a sampled refraction's weight at surface s, for light carried from its
     * normal's side to the other, into the weight of importance carried the same way: (n_o / n_i)^2,
     * as f(a, b) n_a^2 = f(b, a) n_b^2 (docs/conventions.md).
     */
    double adjointTransmission(Surface s) {
        double inside = materials.ior(s.material);
        double ratio = s.front ? 1 / inside : inside;
        return ratio * ratio;
    }

    /** Whether material m lets light through (has a transmission lobe that is not delta). */
    boolean transmits(int m) {
        return (materials.lobes(m) & glint.shading.Lobe.TRANSMISSION) != 0 && !materials.isDelta(m);
    }

    // ---------------------------------------------------------------- densities

    /**
     * A density per solid angle of leaving {@code from} towards {@code to} as a density per unit area at
     * {@code to} (times its cosine where it is on a surface, over the squared distance); unchanged where
     * {@code to} is at infinity. From a far light it is the density of its disc's point, per unit area.
     */
    double toArea(double pdf, BdptVertex from, BdptVertex to) {
        if (to.kind == BdptVertex.FAR) {
            return pdf;
        }
        Surface b = to.surface;
        if (from.kind == BdptVertex.FAR) {
            return to.onSurface() ? pdf * Math.abs(b.nx * from.farX + b.ny * from.farY + b.nz * from.farZ) : pdf;
        }
        Surface a = from.surface;
        double dx = b.px - a.px, dy = b.py - a.py, dz = b.pz - a.pz;
        double distance2 = dx * dx + dy * dy + dz * dz;
        if (!to.onSurface()) {
            return pdf / distance2;
        }
        double cos = Math.abs(b.nx * dx + b.ny * dy + b.nz * dz) / Math.sqrt(distance2);
        return pdf * cos / distance2;
    }

    /** The unit direction from a to b into {@link #w}. */
    private void direction(BdptVertex a, BdptVertex b) {
        if (b.kind == BdptVertex.FAR) {
            w[0] = b.farX;
            w[1] = b.farY;
            w[2] = b.farZ;
        } else if (a.kind == BdptVertex.FAR) {
            w[0] = -a.farX;
            w[1] = -a.farY;
            w[2] = -a.farZ;
        } else {
            double dx = b.surface.px - a.surface.px, dy = b.surface.py - a.surface.py, dz = b.surface.pz - a.surface.pz;
            double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
            w[0] = dx * inv;
            w[1] = dy * inv;
            w[2] = dz * inv;
        }
    }

    /**
     * The density, per unit area at a chain's far end {@code to}, with which {@code from} reaches it
     * through a chain of delta vertices (smooth glass, mirrors), {@code from} sending the path along
     * unit {@code out} with density {@code pdf} and {@code to} entered along unit {@code in}, up to a
     * factor the chain's density the other way shares. Through a chain the true density is pdf times the
     * chain's generalized geometry term G over the cosine at {@code from} (Veach 1997, 8.2.2): G, the
     * footprint of the rays through every curved surface, is the same both ways and cancels in the
     * weights, which use only the two ends' ratio; what is left is pdf over the cosine at {@code from}.
     * To or from infinity, where there is no cosine at the far end: as if the chain were flat mirrors.
     */
    double throughChain(double pdf, BdptVertex from, double outX, double outY, double outZ, BdptVertex to,
                        double inX, double inY, double inZ) {
        if (to.kind == BdptVertex.FAR) {
            return pdf;
        }
        if (from.kind == BdptVertex.FAR) {
            Surface b = to.surface;
            return to.onSurface() ? pdf * Math.abs(b.nx * inX + b.ny * inY + b.nz * inZ) : pdf;
        }
        if (!from.onSurface()) {
            return pdf;
        }
        Surface a = from.surface;
        double cos = Math.abs(a.nx * outX + a.ny * outY + a.nz * outZ);
        return cos > 0 ? pdf / cos : 0;
    }

    /** The density with which vertex v, reached from {@code prev}, sends the path on to {@code next}. */
    double pdf(BdptVertex v, BdptVertex prev, BdptVertex next) {
        if (v.kind == BdptVertex.LIGHT || v.kind == BdptVertex.FAR) {
            return pdfLight(v, next);
        }
        direction(v, next);
        return toArea(pdfToward(v, prev, next, w[0], w[1], w[2]), v, next);
    }

    /**
     * The density per solid angle with which vertex v, reached from {@code prev} (none for a light or the
     * camera), sends the path along unit w to {@code next}; from a far light, the density of its disc's
     * point (for the ray through next: {@link LightTargets#pdfAcross}).
     */
    double pdfToward(BdptVertex v, BdptVertex prev, BdptVertex next, double wx, double wy, double wz) {
        Surface c = v.surface;
        switch (v.kind) {
            case BdptVertex.FAR:
                Surface n = next.surface;
                return targets.pdfAcross(n.px, n.py, n.pz, wx, wy, wz, 1 / (Math.PI * choice.radius * choice.radius));
            case BdptVertex.LIGHT:
                lights.leavingPdf(v.light, c.px, c.py, c.pz, wx, wy, wz, choice.radius, leaving);
                return targets.pdf(c.px, c.py, c.pz, wx, wy, wz, leaving.pdfDirection);
            case BdptVertex.CAMERA:
                return scene.camera.directionPdf(c.px, c.py, c.pz, wx, wy, wz, width, height);
            default:
                direction(v, prev);
                return bsdfPdf(v, w[0], w[1], w[2], wx, wy, wz);
        }
    }

    /** The density with which a light subpath from light vertex v reaches {@code to} first. */
    double pdfLight(BdptVertex v, BdptVertex to) {
        if (v.kind == BdptVertex.FAR
                && !choice.crossesDisc(to.surface.px, to.surface.py, to.surface.pz, v.farX, v.farY, v.farZ)) {
            return 0;
        }
        direction(v, to);
        return toArea(pdfToward(v, null, to, w[0], w[1], w[2]), v, to);
    }

    /**
     * Where {@code end} sends the path back, with density {@code pdf} per solid angle, through the chain
     * of delta vertices before it on its subpath {@code path}, whose last is {@code path[last]}: the
     * density with which it reaches the chain's start, set as the start's reverse density
     * ({@link #throughChain}).
     */
    void backThroughChain(double pdf, BdptVertex end, BdptVertex[] path, int last) {
        int start = chainStart(path, last);
        BdptVertex first = path[start], second = path[start + 1];
        direction(end, path[last]);
        first.pdfRev = throughChain(pdf, end, w[0], w[1], w[2], first, -second.woX, -second.woY, -second.woZ);
    }

    /** The index of the start of the chain of delta vertices that ends at {@code path[last]}. */
    private static int chainStart(BdptVertex[] path, int last) {
        int start = last;
        while (path[start].delta) {
            start--;
        }
        return start;
    }

    /** The density with which a light subpath starts at light vertex v: its light's chance times its point's. */
    double pdfLightOrigin(BdptVertex v) {
        if (v.kind == BdptVertex.FAR) {
            return choice.farDensity(v.farX, v.farY, v.farZ);
        }
        Surface a = v.surface;
        lights.leavingPdf(v.light, a.px, a.py, a.pz, 0, 0, 1, choice.radius, leaving);
        return choice.chance(v.light) * leaving.pdfOrigin;
    }

    /**
     * The vertex of light k that sample {@code ls} of it, from surface s (its near or far side), chose,
     * into {@code out}, with the density a light subpath starts there.
     */
    void lightVertex(int k, Surface s, boolean near, LightSample ls, BdptVertex out) {
        out.light = k;
        out.delta = false;
        out.connectible = false;
        out.deltaLight = lights.isDelta(k);
        if (lights.infinitelyFar(k)) {
            out.kind = BdptVertex.FAR;
            out.setFar(ls.dirX, ls.dirY, ls.dirZ);
            out.pdfFwd = choice.farDensity(ls.dirX, ls.dirY, ls.dirZ);
            return;
        }
        out.kind = BdptVertex.LIGHT;
        double ox = near ? s.nearX() : s.farX(), oy = near ? s.nearY() : s.farY(), oz = near ? s.nearZ() : s.farZ();
        out.setPoint(ox + ls.dirX * ls.distance, oy + ls.dirY * ls.distance, oz + ls.dirZ * ls.distance);
        Surface a = out.surface;
        lights.leavingPdf(k, a.px, a.py, a.pz, -ls.dirX, -ls.dirY, -ls.dirZ, choice.radius, leaving);
        out.setNormal(leaving.normalX, leaving.normalY, leaving.normalZ);
        out.pdfFwd = choice.chance(k) * leaving.pdfOrigin;
    }

    // ---------------------------------------------------------------- the weight

    /**
     * The power heuristic's weight of strategy (s, t) for the path of the light subpath's first s vertices
     * and the camera subpath's first t, joined: 1 / (1 + sum over the other strategies of (p_other /
     * p_this)^2), each ratio the product of the ratios of the two ends' densities at the vertices between.
     * For s = 1 the light vertex is {@code sampledLight}, for t = 1 the camera's {@code sampledCamera}. The
     * joined vertices' reverse densities are set for the sum and restored after it.
     */
    double weight(int s, int t, BdptVertex[] camera, BdptVertex[] light, BdptVertex sampledLight,
                  BdptVertex sampledCamera) {
        if (!weighted) {
            return 1;
        }
        if (s + t == 2) {
            return 1;
        }
        if (!made(s, t, camera, light)) {
            return 0;
        }
        BdptVertex pt = t == 1 ? sampledCamera : camera[t - 1];
        BdptVertex ptMinus = t > 1 ? camera[t - 2] : null;
        BdptVertex qs = s == 0 ? null : s == 1 ? sampledLight : light[s - 1];
        BdptVertex qsMinus = s > 1 ? light[s - 2] : null;
        boolean ptDelta = pt.delta, qsDelta = qs != null && qs.delta;
        save(pt);
        pt.pdfRev = s > 0 ? pdf(qs, qsMinus, pt) : pdfLightOrigin(pt);
        if (ptMinus != null) {
            backFromJoin(pt, qs, ptMinus, camera, t - 2, s > 0);
        }
        if (qs != null) {
            save(qs);
            qs.pdfRev = pdf(pt, ptMinus, qs);
            if (qsMinus != null) {
                backFromJoin(qs, pt, qsMinus, light, s - 2, true);
            }
            qs.delta = false;
        }
        pt.delta = false;
        double sum = otherStrategies(s, t, camera, light, qs,
                choice.nextEventFactor(s == 0 ? pt : s == 1 ? sampledLight : light[0]));
        restore();
        pt.delta = ptDelta;
        if (qs != null) {
            qs.delta = qsDelta;
        }
        return 1 / (1 + sum);
    }

    /**
     * The weight of merging (vertex merging) the last vertex of the light subpath light[0 .. s - 1] (s >= 2),
     * found within the merge radius of camera vertex camera[t - 1] (t >= 2), with it: the power heuristic
     * over every strategy, each join and each merge, that makes the path of the light subpath's first s - 1
     * vertices, the camera's first t and the light subpath's last (Georgiev et al. 2012), worked out as
     * {@link #weight} does from the join (s - 1, t) of the two, which itself cannot make the path where
     * the light subpath reached its last vertex through a delta lobe.
     */
    double mergeWeight(int s, int t, BdptVertex[] camera, BdptVertex[] light) {
        if (!weighted) {
            return 1;
        }
        if (!made(s, t, camera, light)) {
            return 0;
        }
        int b = s - 1;
        BdptVertex pt = camera[t - 1], ptMinus = camera[t - 2], qs = light[b - 1];
        boolean ptDelta = pt.delta;
        save(pt);
        pt.pdfRev = light[b].pdfFwd; // the light's density of reaching the point merged there
        backFromJoin(pt, qs, ptMinus, camera, t - 2, true);
        save(qs);
        boolean joins = !qs.delta;
        if (joins) {
            qs.pdfRev = pdf(pt, ptMinus, qs); // the vertex before qs as its light subpath recorded it
        } else {
            backFromJoin(pt, ptMinus, qs, light, b - 1, true);
        }
        pt.delta = false;
        double q = choice.nextEventFactor(light[0]);
        double sum = otherStrategies(b, t, camera, light, qs, q);
        double merge = pt.pdfRev * eta;
        restore();
        pt.delta = ptDelta;
        double term = merge * merge * (b == 1 ? 1 / (q * q) : 1);
        double total = (joins ? 1 : 0) + sum;
        return total > 0 ? term / total : 0;
    }

    /**
     * Sets the reverse density of {@code back} = path[last], the vertex before {@code joined} on its
     * subpath, for a path that reaches {@code joined} from {@code from} and goes on to {@code back}; where
     * {@code back} is delta, instead the densities through the chain of delta vertices it ends (to its
     * start). {@code scatters}: joined is a surface scattering the path (else a light the camera met).
     */
    private void backFromJoin(BdptVertex joined, BdptVertex from, BdptVertex back, BdptVertex[] path, int last,
                              boolean scatters) {
        save(back);
        if (!back.delta) {
            back.pdfRev = scatters ? pdf(joined, from, back) : pdfLight(joined, back);
            return;
        }
        back.pdfRev = PAST_DELTA;
        save(path[chainStart(path, last)]);
        direction(joined, back);
        backThroughChain(pdfToward(joined, from, back, w[0], w[1], w[2]), joined, path, last);
    }

    /** Vertices whose reverse density a weight changed for the while, and their own, to put back. */
    private final BdptVertex[] savedVertex = new BdptVertex[8];
    private final double[] savedRev = new double[8];
    private int saved;

    private void save(BdptVertex v) {
        savedVertex[saved] = v;
        savedRev[saved++] = v.pdfRev;
    }

    private void restore() {
        while (saved > 0) {
            saved--;
            savedVertex[saved].pdfRev = savedRev[saved];
            savedVertex[saved] = null;
        }
    }

    /**
     * The sum over every strategy but (s, t) of its density over (s, t)'s, squared (the power heuristic),
     * the joined vertices' densities set: each join, each merge where merging is on ({@link #eta}).
     * Next-event estimation's light end is denser by q: its strategy's term counts q^2 more, and every
     * other term q^2 less where next-event estimation is the strategy weighed; light tracing's camera end
     * likewise by {@link #lightTracing}.
     */
    private double otherStrategies(int s, int t, BdptVertex[] camera, BdptVertex[] light, BdptVertex qs, double q) {
        double tracing = lightTracing * lightTracing, weighed = t == 1 ? 1 / tracing : 1;
        double nextEvent = q * q * weighed, others = (s == 1 ? 1 / (q * q) : 1) * weighed;
        double sum = 0, ratio = 1;
        for (int i = t - 1; i > 0; i--) {
            BdptVertex v = camera[i];
            ratio *= v.pdfRev / nonZero(v.pdfFwd);
            if (!v.delta && !camera[i - 1].delta) {
                sum += ratio * ratio * (s + t - i == 1 ? nextEvent : others) * (i == 1 ? tracing : 1);
            }
            if (eta > 0 && merges(v)) { // both ends reach v: the camera's density of it is the chance to merge
                double m = ratio * v.pdfFwd * eta;
                sum += m * m * others;
            }
        }
        ratio = 1;
        for (int i = s - 1; i >= 0; i--) {
            BdptVertex v = i == s - 1 ? qs : light[i];
            ratio *= v.pdfRev / nonZero(v.pdfFwd);
            boolean deltaBefore = i > 0 ? light[i - 1].delta : v.deltaLight;
            if (!v.delta && !deltaBefore) {
                sum += ratio * ratio * (i == 1 ? nextEvent : others);
            }
            if (eta > 0 && i > 0 && merges(v)) {
                double m = ratio * v.pdfFwd * eta;
                sum += m * m * others;
            }
        }
        return sum;
    }

    /**
     * Whether a path may be made by merging at v: a point of a surface with a diffuse lobe
     * ({@link BdptVertex#diffuse}) that scatters it by a lobe that is not delta.
     */
    static boolean merges(BdptVertex v) {
        return v.kind == BdptVertex.SURFACE && v.diffuse && !v.delta;
    }

    /**
     * Whether strategy (s, t) can make the path at all: no vertex of either subpath reached with density 0
     * (a point no light from infinity crosses to, a camera ray off the image).
     */
    private static boolean made(int s, int t, BdptVertex[] camera, BdptVertex[] light) {
        for (int i = 1; i < s; i++) {
            if (light[i].pdfFwd == 0) {
                return false;
            }
        }
        for (int i = 1; i < t; i++) {
            if (camera[i].pdfFwd == 0) {
                return false;
            }
        }
        return true;
    }

    /**
     * A forward density of 0 as 1: only a light's origin has one, where no light at infinity but a delta
     * one (a directional light) could have started the path; that strategy never counts.
     */
    private static double nonZero(double pdf) {
        return pdf != 0 ? pdf : 1;
    }

    /** The BSDF of material m. */
    Bsdf bsdf(int m) {
        return materials.bsdf(m);
    }
}
