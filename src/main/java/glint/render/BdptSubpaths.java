package glint.render;

import glint.geometry.Hit;
import glint.shading.Bsdf;
import glint.shading.BsdfSample;
import glint.shading.LightRay;
import glint.shading.LightTargets;
import glint.shading.Lights;
import glint.shading.Lobe;
import glint.shading.Materials;
import glint.shading.Surface;

/**
 * The two random walks of one render thread's {@link BdptIntegrator}: the camera subpath from a camera
 * ray whose first hit is known, and the light subpath from a ray leaving a light chosen by its power.
 * Each vertex records the densities of the walk both ways that the strategies' weights read
 * ({@link BdptWeights}); the walks draw the integrator's random numbers, a subpath's from its own
 * dimensions. Allocates nothing per path.
 */
final class BdptSubpaths {

    /** Random dimensions a vertex of a subpath uses: the direction (a pair), the lobe and the roulette. */
    private static final int DIMENSIONS_PER_VERTEX = 3;

    private final BdptIntegrator it;
    /** The integrator's numbers, drawn in its path's dimensions. */
    private final PathSamples random;
    private final Hit hit = new Hit();
    private final BsdfSample sampled = new BsdfSample();
    private final LightRay lightRay = new LightRay();

    BdptSubpaths(BdptIntegrator integrator, PathSamples random) {
        this.it = integrator;
        this.random = random;
    }

    /**
     * The camera subpath of the ray from o along d, chosen with density {@code pdfDirection}, into
     * {@code camera} after its first vertex (the lens point, set): its first hit is primitive
     * {@code primitive} at distance t ({@link Hit#NONE}: none), at most {@code most} vertices; returns the
     * count.
     */
    int cameraSubpath(BdptVertex[] camera, int most, double ox, double oy, double oz, double dx, double dy,
                      double dz, double pdfDirection, int primitive, double t) {
        if (primitive != Hit.NONE) {
            it.primitives.record(hit, primitive, t);
        }
        return walk(camera, 1, most, ox, oy, oz, dx, dy, dz, pdfDirection, 1, 1, 1, false, 0,
                primitive != Hit.NONE ? 1 : 0, Hit.NONE, Hit.NONE);
    }

    /**
     * Starts a light subpath, into {@code light}, at a light chosen by its power, from a ray leaving it,
     * drawing from random dimension {@code dimensions} on, and walks it to at most {@code most} vertices;
     * returns its vertex count (0 where the scene has no light).
     */
    int lightSubpath(BdptVertex[] light, int most, int dimensions) {
        RenderScene scene = it.scene;
        BdptWeights weights = it.weights;
        Lights all = scene.lightsAndSky;
        LightChoice choice = weights.choice;
        int k = choice.choose(random.single(dimensions));
        if (k < 0) {
            return 0;
        }
        double chance = choice.chance(k);
        random.pair(dimensions + 1);
        double u1 = random.u1, u2 = random.u2;
        random.pair(dimensions + 2);
        double u3 = random.u1, u4 = random.u2;
        all.leaving(k, choice.centreX, choice.centreY, choice.centreZ, choice.radius, u1, u2, u3, u4, lightRay);
        LightRay ray = lightRay;
        boolean far = all.infinitelyFar(k);
        int target = weights.targets.choose(random.single(dimensions + 3));
        random.pair(dimensions + 4);
        // a far light's first hit is found with the density of the point of its disc
        double pdfDirection = aimed(k, far, target, random.u1, random.u2, ray);
        BdptVertex origin = light[0];
        origin.kind = far ? BdptVertex.FAR : BdptVertex.LIGHT;
        origin.light = k;
        origin.setPoint(ray.originX, ray.originY, ray.originZ);
        origin.setNormal(ray.normalX, ray.normalY, ray.normalZ);
        origin.setFar(-ray.dirX, -ray.dirY, -ray.dirZ);
        origin.deltaLight = all.isDelta(k);
        origin.delta = false;
        origin.connectible = false;
        origin.pdfFwd = far ? choice.farDensity(-ray.dirX, -ray.dirY, -ray.dirZ) : chance * ray.pdfOrigin;
        if (!(ray.pdfOrigin > 0 && ray.pdfDirection > 0)) {
            return 1;
        }
        double share = (far ? ray.pdfOrigin : ray.pdfDirection) / pdfDirection / chance;
        return walk(light, 1, most, ray.originX, ray.originY, ray.originZ, ray.dirX, ray.dirY, ray.dirZ,
                pdfDirection, ray.fluxR * share, ray.fluxG * share, ray.fluxB * share, true, dimensions + 5, -1,
                far || k >= it.lights.count() ? Hit.NONE : scene.bodyOf[k], Hit.NONE);
    }

    /**
     * Turns the ray leaving light k towards {@code target} ({@link LightTargets}, from the numbers u1 and
     * u2), where that is not -1: a light with a position sends it into the target's cone, where its
     * origin lies outside the target, and sets its own density of the new direction; a light at infinity
     * moves its origin into the target's shadow on its disc, whose own density is the same everywhere.
     * Returns the density of the mixture of the light's own rays and the aimed ones: of the direction, or
     * of the disc's point. A light's flux is the same for every direction and point it leaves by
     * ({@link glint.shading.LightSampler#leaving}), so the ray's flux times its own density over the
     * mixture's is what the chosen ray carries.
     */
    private double aimed(int k, boolean far, int target, double u1, double u2, LightRay ray) {
        LightTargets targets = it.weights.targets;
        LightChoice choice = it.weights.choice;
        if (far) {
            if (target >= 0) {
                targets.aimAcross(target, choice.centreX, choice.centreY, choice.centreZ, choice.radius, u1, u2, ray);
            }
            return targets.pdfAcross(ray.originX, ray.originY, ray.originZ, ray.dirX, ray.dirY, ray.dirZ,
                    ray.pdfOrigin);
        }
        if (target >= 0 && targets.aim(target, ray.originX, ray.originY, ray.originZ, u1, u2, ray)) {
            it.scene.lightsAndSky.leavingPdf(k, ray.originX, ray.originY, ray.originZ, ray.dirX, ray.dirY, ray.dirZ,
                    choice.radius, ray);
        }
        return targets.pdf(ray.originX, ray.originY, ray.originZ, ray.dirX, ray.dirY, ray.dirZ, ray.pdfDirection);
    }

    /**
     * Extends the subpath {@code path}, of {@code n} vertices, by a random walk from its last along the ray
     * from o along d, chosen with density {@code pdfDirection} (of the point of a far light's disc, for the
     * ray leaving it), with throughput beta, to at most {@code most} vertices; returns the count. The
     * first hit is already known where {@code known} is 0 (none) or 1 (in {@link #hit}); -1: to be found.
     * A camera subpath that escapes ends at a {@link BdptVertex#FAR} vertex where light at infinity may
     * meet it; one that meets a light's body ends there. Each vertex left records the density of the
     * walk the other way at the vertex before it.
     */
    private int walk(BdptVertex[] path, int n, int most, double ox, double oy, double oz, double dx, double dy,
                     double dz, double pdfDirection, double betaR, double betaG, double betaB, boolean fromLight,
                     int firstDimension, int known, int skip, int inside) {
        RenderScene scene = it.scene;
        BdptWeights weights = it.weights;
        Materials materials = it.materials;
        double scaleR = 1, scaleG = 1, scaleB = 1; // the throughput over the light's, for the roulette
        int dimension = firstDimension;
        // the last vertex that left by a lobe that is not delta, where a chain of delta vertices starts
        int chainFrom = n - 1;
        double chainPdf = pdfDirection, outX = dx, outY = dy, outZ = dz;
        for (int bounce = 1; n < most; bounce++) {
            BdptVertex previous = path[n - 1];
            boolean found = bounce == 1 && known >= 0 ? known == 1 : it.nearest(ox, oy, oz, dx, dy, dz, skip, inside, hit);
            if (!found) {
                if (!fromLight && scene.lightsAndSky.countAtInfinity() > 0) {
                    BdptVertex v = path[n++];
                    v.kind = BdptVertex.FAR;
                    v.light = -1;
                    v.setFar(dx, dy, dz);
                    v.setBeta(betaR, betaG, betaB);
                    v.pdfFwd = previous.delta ? chainPdf : pdfDirection; // through a chain: as if flat mirrors
                    v.delta = false;
                    v.deltaLight = false;
                    v.connectible = false;
                }
                return n;
            }
            BdptVertex v = path[n];
            it.describe(hit, ox, oy, oz, dx, dy, dz, v.surface);
            v.kind = BdptVertex.SURFACE;
            v.woX = -dx;
            v.woY = -dy;
            v.woZ = -dz;
            v.setBeta(betaR, betaG, betaB);
            v.pdfFwd = previous.delta ? weights.throughChain(chainPdf, path[chainFrom], outX, outY, outZ, v, dx, dy, dz)
                    : weights.toArea(pdfDirection, previous, v);
            v.delta = false;
            v.deltaLight = false;
            int body = scene.lightOf[hit.primitive];
            if (body >= 0) { // a light's black body: light paths end in it, camera paths find its light
                if (fromLight) {
                    return n;
                }
                v.kind = BdptVertex.LIGHT;
                v.light = body;
                v.connectible = false;
                return n + 1;
            }
            Surface s = v.surface;
            v.connectible = !materials.isDelta(s.material);
            v.diffuse = (materials.lobes(s.material) & Lobe.DIFFUSE) != 0;
            n++;
            if (n == most) {
                return n;
            }
            random.pair(dimension);
            Bsdf bsdf = materials.bsdf(s.material);
            BsdfSample next = sampled;
            if (!bsdf.sample(materials, s, -dx, -dy, -dz, random.u1, random.u2, random.single(dimension + 1), next)) {
                return n;
            }
            double adjoint = fromLight && next.transmitted() ? weights.adjointTransmission(s) : 1;
            v.delta = next.delta();
            pdfDirection = next.pdf;
            if (v.delta) { // a chain goes on: its densities are its ends'
                v.pdfFwd = v.pdfFwd != 0 ? BdptWeights.PAST_DELTA : 0;
                previous.pdfRev = BdptWeights.PAST_DELTA;
            } else {
                double back = weights.bsdfPdf(v, next.wiX, next.wiY, next.wiZ, v.woX, v.woY, v.woZ);
                if (previous.delta) { // a chain ends at v
                    previous.pdfRev = BdptWeights.PAST_DELTA;
                    weights.backThroughChain(back, v, path, n - 2);
                } else {
                    previous.pdfRev = weights.toArea(back, v, previous);
                }
                chainFrom = n - 1;
                chainPdf = next.pdf;
                outX = next.wiX;
                outY = next.wiY;
                outZ = next.wiZ;
            }
            double wr = next.weightR * adjoint, wg = next.weightG * adjoint, wb = next.weightB * adjoint;
            betaR *= wr;
            betaG *= wg;
            betaB *= wb;
            scaleR *= wr;
            scaleG *= wg;
            scaleB *= wb;
            if (bounce >= PathIntegrator.ROULETTE_FROM) {
                double survive = Math.min(1, Math.max(scaleR, Math.max(scaleG, scaleB)));
                if (!(random.single(dimension + 2) < survive)) {
                    return n;
                }
                betaR /= survive;
                betaG /= survive;
                betaB /= survive;
                scaleR /= survive;
                scaleG /= survive;
                scaleB /= survive;
            }
            boolean through = next.transmitted();
            ox = through ? s.farX() : s.nearX();
            oy = through ? s.farY() : s.nearY();
            oz = through ? s.farZ() : s.nearZ();
            skip = through ? s.skipFar : s.skipNear;
            inside = through ? s.insideFar : s.insideNear;
            dx = next.wiX;
            dy = next.wiY;
            dz = next.wiZ;
            dimension += DIMENSIONS_PER_VERTEX;
        }
        return n;
    }
}
