package glint.bench;

import glint.render.Intersect;
import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;

/**
 * Up to four spheres tested against one ray at once with the Vector API (one AVX2 register of four
 * doubles per coordinate): the same arithmetic as {@link Intersect#sphereBefore}, lane by lane and in
 * the same order, so the distances are bit for bit the scalar ones. A measuring prototype for
 * {@link SphereTestBenchmark}; the renderer itself stays scalar (docs/benchmarks.md says why).
 */
final class SphereGroup {

    private static final VectorSpecies<Double> LANES = DoubleVector.SPECIES_256;

    private final double[] centreX = new double[4];
    private final double[] centreY = new double[4];
    private final double[] centreZ = new double[4];
    private final double[] radius = new double[4];
    private final VectorMask<Double> used;

    /** The group of spheres {@code spheres[4i..4i+3]} = centre x, y, z, radius; at most four. */
    SphereGroup(double[] spheres) {
        int count = spheres.length / 4;
        if (count > 4) {
            throw new IllegalArgumentException("at most 4 spheres in a group, not " + count);
        }
        for (int i = 0; i < count; i++) {
            centreX[i] = spheres[4 * i];
            centreY[i] = spheres[4 * i + 1];
            centreZ[i] = spheres[4 * i + 2];
            radius[i] = spheres[4 * i + 3];
        }
        used = VectorMask.fromLong(LANES, (1L << count) - 1);
    }

    /** The index of the sphere of the last {@link #nearest} hit, or -1. */
    int hitSphere;

    /** Nearest t in (0, tMax) over the group's spheres, or {@link Intersect#MISS}; sets hitSphere. */
    double nearest(double ox, double oy, double oz, double dx, double dy, double dz, double tMax) {
        DoubleVector r = DoubleVector.fromArray(LANES, radius, 0);
        DoubleVector fx = DoubleVector.broadcast(LANES, ox).sub(DoubleVector.fromArray(LANES, centreX, 0));
        DoubleVector fy = DoubleVector.broadcast(LANES, oy).sub(DoubleVector.fromArray(LANES, centreY, 0));
        DoubleVector fz = DoubleVector.broadcast(LANES, oz).sub(DoubleVector.fromArray(LANES, centreZ, 0));
        DoubleVector rSquared = r.mul(r);
        DoubleVector c = fx.mul(fx).add(fy.mul(fy)).add(fz.mul(fz)).sub(rSquared);
        DoubleVector b = fx.mul(dx).add(fy.mul(dy)).add(fz.mul(dz)).neg();
        VectorMask<Double> outside = c.compare(VectorOperators.GT, 0.0);
        VectorMask<Double> candidate = used.andNot(outside.and(b.compare(VectorOperators.LE, 0.0)))
                .andNot(b.sub(r).compare(VectorOperators.GE, tMax));
        DoubleVector hx = fx.add(b.mul(dx)), hy = fy.add(b.mul(dy)), hz = fz.add(b.mul(dz));
        DoubleVector discriminant = rSquared.sub(hx.mul(hx).add(hy.mul(hy)).add(hz.mul(hz)));
        candidate = candidate.andNot(discriminant.compare(VectorOperators.LT, 0.0));
        if (!candidate.anyTrue()) {
            hitSphere = -1;
            return Intersect.MISS;
        }
        DoubleVector root = discriminant.lanewise(VectorOperators.SQRT);
        DoubleVector farRoot = b.add(root);
        DoubleVector t = c.div(farRoot) // outside: the near root
                .blend(farRoot, outside.not()) // inside, b >= 0: the far root
                .blend(c.div(b.sub(root)), outside.not().and(b.compare(VectorOperators.LT, 0.0)));
        candidate = candidate.and(t.compare(VectorOperators.GT, 0.0)).and(t.compare(VectorOperators.LT, tMax));
        DoubleVector hits = DoubleVector.broadcast(LANES, Intersect.MISS).blend(t, candidate);
        double nearest = hits.reduceLanes(VectorOperators.MIN);
        hitSphere = nearest < tMax ? hits.compare(VectorOperators.EQ, nearest).firstTrue() : -1;
        return nearest < tMax ? nearest : Intersect.MISS;
    }
}
