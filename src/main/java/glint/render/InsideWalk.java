package glint.render;

import glint.geometry.Hit;
import glint.geometry.PrimitiveKind;
import glint.geometry.Primitives;
import glint.shading.Optics;
import glint.shading.Rgb;
import glint.shading.ShadingModel;
import glint.shading.SingleRays;
import glint.shading.Surface;

/**
 * How a ray refracted into a closed primitive that nothing else reaches into is traced: it can only
 * bounce inside it, and at each bounce a ray leaves through the surface while the rest reflects on.
 * The kind gives each chord in closed form ({@link PrimitiveKind#chordInside}), so no bounce searches the
 * scene; where the cosine at a bounce is the one before (every bounce of a sphere), the boundary's
 * factors and the bend of the ray leaving are not worked out again. The radiance is what
 * {@link WhittedIntegrator#trace} would find, to rounding, and the roulette's numbers are drawn in the same
 * order: first each bounce's reflected ray, going in, then each leaving ray, from the deepest bounce
 * out, as the recursion draws them. The walk keeps what it learns of each bounce going in and reads
 * it coming out in a {@link Bounce} of its own, one per level of recursion: a ray leaving bounce k
 * (traced with fewer hits left) may walk another inside, which overwrites only deeper bounces, done
 * with by then.
 */
final class InsideWalk {

    /**
     * What the walk knows of the bounce at one level, from going in until coming out: a path vertex
     * (its {@code sum} the light the bounce sends back by itself, its {@code refracted} the direction
     * of the ray leaving it) and the walk's own three values.
     */
    private static final class Bounce extends PathVertex {
        boolean leavesThrough;
        /** The path weight of the ray that met the bounce, and what its reflected ray counts for (0: not traced). */
        double weight, keepReflected;
    }

    private final WhittedIntegrator it;
    private Bounce[] bounces = new Bounce[0];

    InsideWalk(WhittedIntegrator integrator) {
        this.it = integrator;
    }

    /** Makes room for a walk of up to {@code recursionMax} hits. */
    void prepare(int recursionMax) {
        if (bounces.length <= recursionMax) {
            Bounce[] grown = new Bounce[recursionMax + 1];
            for (int i = 0; i < grown.length; i++) {
                grown[i] = i < bounces.length ? bounces[i] : new Bounce();
            }
            bounces = grown;
        }
    }

    /**
     * The radiance of the ray refracted through {@code entry} (which it enters on its outer side)
     * along unit u, with {@code hitsLeft} hits and path weight {@code weight}: a scratch value, to read
     * before the walk is asked again.
     */
    Rgb trace(Surface entry, double ux, double uy, double uz, int hitsLeft, double weight) {
        int primitive = entry.insideFar;
        int deepest = walkIn(entry, ux, uy, uz, hitsLeft, weight);
        double r = 0, g = 0, b = 0;
        if (deepest > hitsLeft || bounces[deepest].keepReflected > 0) { // the search traced the rest
            Rgb rest = bounces[deepest - 1].radiance;
            r = rest.r;
            g = rest.g;
            b = rest.b;
        }
        for (int level = deepest; level <= hitsLeft; level++) {
            Bounce v = bounces[level];
            double sumR = v.sum.r, sumG = v.sum.g, sumB = v.sum.b;
            SingleRays rays = v.rays;
            if (v.keepReflected > 0) {
                double k = v.keepReflected;
                sumR += k * rays.reflectR * r;
                sumG += k * rays.reflectG * g;
                sumB += k * rays.reflectB * b;
            }
            if (level > 1) {
                double childWeight = v.weight * rays.transmitMax();
                double keep = childWeight > 0 ? it.keep(childWeight) : 0;
                if (keep > 0) {
                    Rgb left = leave(v, primitive, level, childWeight * keep);
                    sumR += keep * rays.transmitR * left.r;
                    sumG += keep * rays.transmitG * left.g;
                    sumB += keep * rays.transmitB * left.b;
                }
            }
            v.radiance.set(sumR, sumG, sumB);
            r = v.radiance.r; // as set (bounded), as the recursion passes it on
            g = v.radiance.g;
            b = v.radiance.b;
        }
        return bounces[hitsLeft].radiance;
    }

    /**
     * Follows the chords in: at each bounce, its surface, its own light and boundary, the direction
     * of the ray leaving it, and the roulette of the ray reflected on. Returns the level of the
     * deepest bounce walked (hitsLeft + 1 for none). Where the kind gives no closed form, the rest
     * is traced by the search, into the radiance of the level below that bounce, and the bounce's
     * reflected ray is kept.
     */
    private int walkIn(Surface entry, double ux, double uy, double uz, int hitsLeft, double weight) {
        int primitive = entry.insideFar;
        Primitives primitives = it.primitives();
        PrimitiveKind kind = primitives.kind(primitives.kindOf(primitive));
        int index = primitives.indexOf(primitive), material = it.materialOf(primitive);
        ShadingModel model = it.model();
        double px = entry.px, py = entry.py, pz = entry.pz; // where the chord starts, on the surface
        double sx = entry.farX(), sy = entry.farY(), sz = entry.farZ(); // where a searched ray would start
        double cos = -(ux * entry.nx + uy * entry.ny + uz * entry.nz), offset = entry.offset;
        double bend = Double.NaN;
        double weightIn = weight;
        Bounce previous = null;
        for (int level = hitsLeft; ; level--) {
            Bounce v = bounces[level];
            Hit end = v.hit;
            double cosEnd = kind.chordInside(index, px, py, pz, ux, uy, uz, cos, offset, end);
            if (Double.isNaN(cosEnd)) {
                Rgb rest = it.trace(sx, sy, sz, ux, uy, uz, level, weightIn, Hit.NONE, primitive);
                v.radiance.set(rest.r, rest.g, rest.b);
                return level + 1;
            }
            it.countRay();
            Surface s = v.surface;
            s.setInside(end, cosEnd, it.epsilon(), material, primitive);
            it.direct(v, ux, uy, uz, level);
            SingleRays rays = v.rays;
            boolean sameAngle = previous != null && cosEnd == previous.surface.cosIncident;
            if (sameAngle) {
                rays.setTo(previous.rays);
            } else {
                model.specular(it, s, rays);
                bend = Optics.refractionBend(cosEnd, rays.eta);
            }
            v.weight = weightIn;
            v.keepReflected = 0;
            v.leavesThrough = !Double.isNaN(bend);
            double[] out = v.refracted;
            if (v.leavesThrough) {
                Optics.refractWithBend(ux, uy, uz, s.nx, s.ny, s.nz, rays.eta, bend, out);
            } else { // past the critical angle the leaving ray reflects: keep the incoming direction
                out[0] = ux;
                out[1] = uy;
                out[2] = uz;
            }
            if (level <= 1) {
                return level;
            }
            double reflect = rays.reflectMax();
            v.keepReflected = it.keep(weightIn * reflect);
            if (!(v.keepReflected > 0)) {
                return level;
            }
            weightIn *= reflect * v.keepReflected;
            double k = 2 * cosEnd;
            ux += k * s.nx;
            uy += k * s.ny;
            uz += k * s.nz;
            px = s.px;
            py = s.py;
            pz = s.pz;
            sx = s.nearX();
            sy = s.nearY();
            sz = s.nearZ();
            cos = cosEnd;
            offset = s.offset;
            previous = v;
        }
    }

    /** Traces the ray leaving bounce v (at {@code level}) through the surface, or past the critical angle reflected. */
    private Rgb leave(Bounce v, int primitive, int level, double weight) {
        Surface s = v.surface;
        double[] d = v.refracted;
        if (v.leavesThrough) {
            return it.trace(s.farX(), s.farY(), s.farZ(), d[0], d[1], d[2], level - 1, weight, primitive, Hit.NONE);
        }
        return it.traceReflected(s, d[0], d[1], d[2], level, weight);
    }
}
