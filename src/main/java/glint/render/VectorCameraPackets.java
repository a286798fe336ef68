package glint.render;

import static jdk.incubator.vector.VectorOperators.GE;
import static jdk.incubator.vector.VectorOperators.GT;
import static jdk.incubator.vector.VectorOperators.LT;
import static jdk.incubator.vector.VectorOperators.NE;

import glint.config.Shading;
import java.util.Arrays;
import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorSpecies;

/**
 * {@link CameraPackets} through the Vector API: one AVX2 register of four doubles holds one
 * coordinate of the four rays. Every lane does what {@link RayCaster#nearestFromEye},
 * {@link TracerWorker#trace} and its matte shading do for one ray, operation for operation in the
 * same order, with masks where they branch: the radiance is theirs bit for bit. Loaded only
 * where the JVM has the module ({@link CameraPackets#load}); one per worker.
 *
 * <p>Vectors never cross a method call: a vector passed to or returned from a method the JIT
 * does not inline is allocated on the heap, and the JIT inlines little of code this size. The
 * methods hand their lanes over in the small arrays below instead, and each is a whole step.
 */
final class VectorCameraPackets implements CameraPackets {

    private static final VectorSpecies<Double> SPECIES = DoubleVector.SPECIES_256;
    private static final double INV_PI = 1 / Math.PI;

    // lanes handed from one step to the next: the hit distances, then hit points, normals and
    // offsets, then per light the shadow rays' directions and lengths, and which lanes they block
    private final double[] hitT = new double[LANES], hitId = new double[LANES];
    private final double[] pointX = new double[LANES], pointY = new double[LANES], pointZ = new double[LANES];
    private final double[] normalX = new double[LANES], normalY = new double[LANES], normalZ = new double[LANES];
    private final double[] offset = new double[LANES];
    private final double[] toLightX = new double[LANES], toLightY = new double[LANES], toLightZ = new double[LANES];
    private final double[] lightDistance = new double[LANES];
    private final double[] originX = new double[LANES], originY = new double[LANES], originZ = new double[LANES];
    /** 1 in the lanes whose shadow ray is asked about, then 1 in those the light reaches. */
    private final double[] shadowLanes = new double[LANES];
    // per light: n.l and the inverse square falloff (1 for a directional light)
    private final double[] cosLight = new double[LANES], falloff = new double[LANES];
    // the Lambert sums of the packet's lanes, added to light by light
    private final double[] sumR = new double[LANES], sumG = new double[LANES], sumB = new double[LANES];

    @Override
    public boolean handles(RenderScene scene) {
        return scene.bvh == null && scene.settings.shading() == Shading.COOK_TORRANCE;
    }

    @Override
    public boolean trace(RenderScene s, RayCaster eye, double[] dirX, double[] dirY, double[] dirZ, int first,
                         double[] radianceR, double[] radianceG, double[] radianceB) {
        int id = nearest(s, eye, dirX, dirY, dirZ, first);
        if (id == MIXED) {
            return false;
        }
        if (id == 0) {
            eye.rays += LANES;
            DoubleVector.broadcast(SPECIES, s.backgroundR).intoArray(radianceR, first);
            DoubleVector.broadcast(SPECIES, s.backgroundG).intoArray(radianceG, first);
            DoubleVector.broadcast(SPECIES, s.backgroundB).intoArray(radianceB, first);
            return true;
        }
        int sphere = id > 0 ? id - 1 : -1;
        int plane = id < 0 ? -id - 1 : -1;
        int material = sphere >= 0 ? s.sphereMaterial[sphere] : s.planeMaterial[plane];
        if (s.materialType[material] != RenderScene.MATTE || !surfacePoints(s, sphere, plane, dirX, dirY, dirZ, first)) {
            return false;
        }
        Arrays.fill(sumR, 0);
        Arrays.fill(sumG, 0);
        Arrays.fill(sumB, 0);
        for (int light = 0; light < s.lightCount; light++) {
            if (aimShadowRays(s, light)) {
                eye.rays += shadowRayCount();
                findBlocked(s, id);
                addLight(s, light);
            }
        }
        eye.rays += LANES;
        writeMatte(s, material, first, radianceR, radianceG, radianceB);
        return true;
    }

    /** What {@link #nearest} returns when the lanes meet different surfaces. */
    private static final int MIXED = Integer.MIN_VALUE;

    /**
     * RayCaster.nearestFromEye for the four rays: into hitT, each lane's distance; returns the
     * surface id they all meet (RayCaster.surfaceId; 0 = none), or MIXED.
     */
    private int nearest(RenderScene s, RayCaster eye, double[] dirX, double[] dirY, double[] dirZ, int first) {
        DoubleVector dx = DoubleVector.fromArray(SPECIES, dirX, first);
        DoubleVector dy = DoubleVector.fromArray(SPECIES, dirY, first);
        DoubleVector dz = DoubleVector.fromArray(SPECIES, dirZ, first);
        DoubleVector miss = DoubleVector.broadcast(SPECIES, Intersect.MISS);
        DoubleVector nearestT = miss;
        DoubleVector id = DoubleVector.zero(SPECIES);
        double[] spheres = s.spheres, toCentre = eye.eyeToCentre(), eyeC = eye.eyeC();
        int[] candidates = eye.eyeCandidates();
        for (int j = 0, n = eye.eyeCandidateCount(); j < n; j++) {
            // Intersect.sphereFrom, with f = eye - centre and c = f.f - r^2 shared by the lanes
            int i = candidates[j];
            double fx = toCentre[3 * i], fy = toCentre[3 * i + 1], fz = toCentre[3 * i + 2];
            double c = eyeC[i], radius = spheres[4 * i + 3];
            DoubleVector b = dx.mul(fx).add(dy.mul(fy)).add(dz.mul(fz)).neg();
            VectorMask<Double> live = b.sub(radius).compare(LT, nearestT);
            if (c > 0) {
                live = live.and(b.compare(GT, 0));
            }
            DoubleVector hx = dx.mul(b).add(fx), hy = dy.mul(b).add(fy), hz = dz.mul(b).add(fz);
            DoubleVector discriminant = DoubleVector.broadcast(SPECIES, radius * radius)
                    .sub(hx.mul(hx).add(hy.mul(hy)).add(hz.mul(hz)));
            live = live.and(discriminant.compare(GE, 0));
            DoubleVector root = discriminant.sqrt();
            DoubleVector cs = DoubleVector.broadcast(SPECIES, c);
            // inside: b + root, or c / (b - root) moving away from the centre; outside: c / (b + root)
            DoubleVector t = b.add(root).blend(cs.div(b.sub(root)), b.compare(LT, 0))
                    .blend(cs.div(b.add(root)), c > 0 ? live : live.andNot(live));
            VectorMask<Double> nearer = live.and(t.compare(GT, 0)).and(t.compare(LT, nearestT));
            nearestT = nearestT.blend(t, nearer);
            id = id.blend((double) RayCaster.surfaceId(i, -1), nearer);
        }
        double[] planes = s.planes, numerators = eye.eyePlaneNumerator();
        for (int i = 0, n = s.planeCount; i < n; i++) {
            // Intersect.planeFrom, with the numerator shared by the lanes
            int k = 4 * i;
            double numerator = numerators[i];
            DoubleVector denominator = dx.mul(planes[k]).add(dy.mul(planes[k + 1])).add(dz.mul(planes[k + 2]));
            VectorMask<Double> nearer = denominator.mul(numerator).compare(GT, 0)
                    .and(nearestT.mul(denominator.abs()).compare(GT, Math.abs(numerator)));
            DoubleVector t = DoubleVector.broadcast(SPECIES, numerator).div(denominator);
            nearer = nearer.and(t.compare(LT, nearestT));
            nearestT = nearestT.blend(t, nearer);
            id = id.blend((double) RayCaster.surfaceId(-1, i), nearer);
        }
        nearestT.intoArray(hitT, 0);
        // compared lane by lane from an array: extracting a lane from the register allocates on JDK 17
        id.intoArray(hitId, 0);
        double common = hitId[0];
        return hitId[1] == common && hitId[2] == common && hitId[3] == common ? (int) common : MIXED;
    }

    /**
     * TracerWorker.trace from the hit to the shading, for a sphere or a plane met by all lanes: the
     * hit points, offsets and normals, into their arrays. False when a lane meets the surface from
     * behind (the plain path turns the normal round there; packets leave that to it).
     */
    private boolean surfacePoints(RenderScene s, int sphere, int plane, double[] dirX, double[] dirY, double[] dirZ,
                                  int first) {
        hitPoints(s, dirX, dirY, dirZ, first);
        if (sphere >= 0) {
            onSphere(s, sphere);
        } else {
            onPlane(s, plane);
        }
        return facing(dirX, dirY, dirZ, first);
    }

    /** The hit points eye + t d and their offsets epsilon max(1, |p|). */
    private void hitPoints(RenderScene s, double[] dirX, double[] dirY, double[] dirZ, int first) {
        DoubleVector t = DoubleVector.fromArray(SPECIES, hitT, 0);
        CameraBasis camera = s.camera;
        DoubleVector px = DoubleVector.fromArray(SPECIES, dirX, first).mul(t).add(camera.eyeX);
        DoubleVector py = DoubleVector.fromArray(SPECIES, dirY, first).mul(t).add(camera.eyeY);
        DoubleVector pz = DoubleVector.fromArray(SPECIES, dirZ, first).mul(t).add(camera.eyeZ);
        DoubleVector distance = px.mul(px).add(py.mul(py)).add(pz.mul(pz)).sqrt();
        DoubleVector.broadcast(SPECIES, 1).blend(distance, distance.compare(GT, 1)).mul(s.settings.epsilon())
                .intoArray(offset, 0);
        px.intoArray(pointX, 0);
        py.intoArray(pointY, 0);
        pz.intoArray(pointZ, 0);
    }

    /** Normals of sphere i at the hit points, and the points re-projected onto it. */
    private void onSphere(RenderScene s, int i) {
        int k = 4 * i;
        double cx = s.spheres[k], cy = s.spheres[k + 1], cz = s.spheres[k + 2], radius = s.spheres[k + 3];
        DoubleVector ex = DoubleVector.fromArray(SPECIES, pointX, 0).sub(cx);
        DoubleVector ey = DoubleVector.fromArray(SPECIES, pointY, 0).sub(cy);
        DoubleVector ez = DoubleVector.fromArray(SPECIES, pointZ, 0).sub(cz);
        DoubleVector inv = DoubleVector.broadcast(SPECIES, 1).div(ex.mul(ex).add(ey.mul(ey)).add(ez.mul(ez)).sqrt());
        DoubleVector nx = ex.mul(inv), ny = ey.mul(inv), nz = ez.mul(inv);
        nx.intoArray(normalX, 0);
        ny.intoArray(normalY, 0);
        nz.intoArray(normalZ, 0);
        nx.mul(radius).add(cx).intoArray(pointX, 0);
        ny.mul(radius).add(cy).intoArray(pointY, 0);
        nz.mul(radius).add(cz).intoArray(pointZ, 0);
    }

    /** Plane i's normal in every lane, and the hit points projected onto it. */
    private void onPlane(RenderScene s, int i) {
        int k = 4 * i;
        double nx = s.planes[k], ny = s.planes[k + 1], nz = s.planes[k + 2];
        DoubleVector px = DoubleVector.fromArray(SPECIES, pointX, 0);
        DoubleVector py = DoubleVector.fromArray(SPECIES, pointY, 0);
        DoubleVector pz = DoubleVector.fromArray(SPECIES, pointZ, 0);
        DoubleVector off = px.mul(nx).add(py.mul(ny)).add(pz.mul(nz)).sub(s.planes[k + 3]);
        px.sub(off.mul(nx)).intoArray(pointX, 0);
        py.sub(off.mul(ny)).intoArray(pointY, 0);
        pz.sub(off.mul(nz)).intoArray(pointZ, 0);
        Arrays.fill(normalX, nx);
        Arrays.fill(normalY, ny);
        Arrays.fill(normalZ, nz);
    }

    /** Whether every ray meets the surface from its front: -(d.n) >= 0. */
    private boolean facing(double[] dirX, double[] dirY, double[] dirZ, int first) {
        return DoubleVector.fromArray(SPECIES, dirX, first).mul(DoubleVector.fromArray(SPECIES, normalX, 0))
                .add(DoubleVector.fromArray(SPECIES, dirY, first).mul(DoubleVector.fromArray(SPECIES, normalY, 0)))
                .add(DoubleVector.fromArray(SPECIES, dirZ, first).mul(DoubleVector.fromArray(SPECIES, normalZ, 0)))
                .neg().compare(GE, 0).allTrue();
    }

    /**
     * TracerWorker.lightAt for the four points: the unit directions to the light, the distances,
     * n.l and the falloff, into their arrays, and 1 in shadowLanes where the point faces the light
     * (n.l > 0). Returns whether any lane does.
     */
    private boolean aimShadowRays(RenderScene s, int light) {
        if (s.lightIsPoint[light]) {
            towardsPoint(s, light);
        } else {
            alongDirection(s, light);
        }
        DoubleVector cos = DoubleVector.fromArray(SPECIES, toLightX, 0).mul(DoubleVector.fromArray(SPECIES, normalX, 0))
                .add(DoubleVector.fromArray(SPECIES, toLightY, 0).mul(DoubleVector.fromArray(SPECIES, normalY, 0)))
                .add(DoubleVector.fromArray(SPECIES, toLightZ, 0).mul(DoubleVector.fromArray(SPECIES, normalZ, 0)));
        VectorMask<Double> lit = DoubleVector.fromArray(SPECIES, shadowLanes, 0).compare(NE, 0)
                .and(cos.compare(GT, 0));
        cos.intoArray(cosLight, 0);
        DoubleVector.zero(SPECIES).blend(1.0, lit).intoArray(shadowLanes, 0);
        return lit.anyTrue();
    }

    /** Towards point light i: directions, distances, 1 / distance^2, and 1 in shadowLanes where the distance is not 0. */
    private void towardsPoint(RenderScene s, int light) {
        int j = 3 * light;
        DoubleVector lx = DoubleVector.fromArray(SPECIES, pointX, 0).neg().add(s.lightVector[j]);
        DoubleVector ly = DoubleVector.fromArray(SPECIES, pointY, 0).neg().add(s.lightVector[j + 1]);
        DoubleVector lz = DoubleVector.fromArray(SPECIES, pointZ, 0).neg().add(s.lightVector[j + 2]);
        DoubleVector distance2 = lx.mul(lx).add(ly.mul(ly)).add(lz.mul(lz));
        DoubleVector inv = DoubleVector.broadcast(SPECIES, 1).div(distance2.sqrt());
        distance2.mul(inv).intoArray(lightDistance, 0);
        lx.mul(inv).intoArray(toLightX, 0);
        ly.mul(inv).intoArray(toLightY, 0);
        lz.mul(inv).intoArray(toLightZ, 0);
        inv.mul(inv).intoArray(falloff, 0);
        DoubleVector.zero(SPECIES).blend(1.0, distance2.compare(NE, 0)).intoArray(shadowLanes, 0);
    }

    /** Along directional light i: its direction, no distance limit, no falloff. */
    private void alongDirection(RenderScene s, int light) {
        int j = 3 * light;
        Arrays.fill(toLightX, s.lightVector[j]);
        Arrays.fill(toLightY, s.lightVector[j + 1]);
        Arrays.fill(toLightZ, s.lightVector[j + 2]);
        Arrays.fill(lightDistance, Double.POSITIVE_INFINITY);
        Arrays.fill(falloff, 1);
        Arrays.fill(shadowLanes, 1);
    }

    private int shadowRayCount() {
        int count = 0;
        for (double lane : shadowLanes) {
            count += lane != 0 ? 1 : 0;
        }
        return count;
    }

    /**
     * RayCaster.occluded for the shadow rays of the lanes in shadowLanes, from the offset points:
     * leaves 1 in shadowLanes only where nothing but surface {@code self} lies before the light.
     * Planes and spheres are searched in separate methods: in one, the JIT would stop inlining the
     * Vector API's calls part way (it caps the size of a compiled method) and allocate their results.
     */
    private void findBlocked(RenderScene s, int self) {
        DoubleVector off = DoubleVector.fromArray(SPECIES, offset, 0);
        DoubleVector.fromArray(SPECIES, pointX, 0).add(off.mul(DoubleVector.fromArray(SPECIES, normalX, 0)))
                .intoArray(originX, 0);
        DoubleVector.fromArray(SPECIES, pointY, 0).add(off.mul(DoubleVector.fromArray(SPECIES, normalY, 0)))
                .intoArray(originY, 0);
        DoubleVector.fromArray(SPECIES, pointZ, 0).add(off.mul(DoubleVector.fromArray(SPECIES, normalZ, 0)))
                .intoArray(originZ, 0);
        for (int i = 0, n = s.planeCount; i < n; i++) {
            if (RayCaster.surfaceId(-1, i) != self && !blockedByPlane(s.planes, 4 * i)) {
                return;
            }
        }
        for (int i = 0, n = s.sphereCount; i < n; i++) {
            if (RayCaster.surfaceId(i, -1) != self && !blockedBySphere(s.spheres, 4 * i)) {
                return;
            }
        }
    }

    /**
     * Intersect.planeBefore for the shadow rays still open in shadowLanes, against the plane at
     * planes[k..k+3]: clears the lanes it blocks; returns whether any lane is still open.
     */
    private boolean blockedByPlane(double[] planes, int k) {
        double nx = planes[k], ny = planes[k + 1], nz = planes[k + 2];
        DoubleVector numerator = DoubleVector.fromArray(SPECIES, originX, 0).mul(nx)
                .add(DoubleVector.fromArray(SPECIES, originY, 0).mul(ny))
                .add(DoubleVector.fromArray(SPECIES, originZ, 0).mul(nz)).neg().add(planes[k + 3]);
        DoubleVector denominator = DoubleVector.fromArray(SPECIES, toLightX, 0).mul(nx)
                .add(DoubleVector.fromArray(SPECIES, toLightY, 0).mul(ny))
                .add(DoubleVector.fromArray(SPECIES, toLightZ, 0).mul(nz));
        DoubleVector tMax = DoubleVector.fromArray(SPECIES, lightDistance, 0);
        VectorMask<Double> hit = numerator.mul(denominator).compare(GT, 0)
                .and(numerator.abs().compare(LT, tMax.mul(denominator.abs())))
                .and(numerator.div(denominator).compare(LT, tMax));
        return closeLanes(hit);
    }

    /**
     * Intersect.sphereBefore for the shadow rays still open in shadowLanes, against the sphere at
     * spheres[k..k+3]: clears the lanes it blocks; returns whether any lane is still open.
     */
    private boolean blockedBySphere(double[] spheres, int k) {
        double radius = spheres[k + 3];
        DoubleVector dx = DoubleVector.fromArray(SPECIES, toLightX, 0);
        DoubleVector dy = DoubleVector.fromArray(SPECIES, toLightY, 0);
        DoubleVector dz = DoubleVector.fromArray(SPECIES, toLightZ, 0);
        DoubleVector tMax = DoubleVector.fromArray(SPECIES, lightDistance, 0);
        DoubleVector fx = DoubleVector.fromArray(SPECIES, originX, 0).sub(spheres[k]);
        DoubleVector fy = DoubleVector.fromArray(SPECIES, originY, 0).sub(spheres[k + 1]);
        DoubleVector fz = DoubleVector.fromArray(SPECIES, originZ, 0).sub(spheres[k + 2]);
        DoubleVector c = fx.mul(fx).add(fy.mul(fy)).add(fz.mul(fz)).sub(radius * radius);
        DoubleVector b = fx.mul(dx).add(fy.mul(dy)).add(fz.mul(dz)).neg();
        VectorMask<Double> outside = c.compare(GT, 0);
        VectorMask<Double> live = b.sub(radius).compare(LT, tMax).andNot(outside.andNot(b.compare(GT, 0)));
        DoubleVector hx = dx.mul(b).add(fx), hy = dy.mul(b).add(fy), hz = dz.mul(b).add(fz);
        DoubleVector discriminant = DoubleVector.broadcast(SPECIES, radius * radius)
                .sub(hx.mul(hx).add(hy.mul(hy)).add(hz.mul(hz)));
        live = live.and(discriminant.compare(GE, 0));
        if (!live.anyTrue()) {
            return true;
        }
        DoubleVector root = discriminant.sqrt();
        DoubleVector farRoot = b.add(root);
        // outside: c / (b + root); inside: b + root, or c / (b - root) moving away from the centre
        DoubleVector t = c.div(b.sub(root)).blend(farRoot, b.compare(GE, 0)).blend(c.div(farRoot), outside);
        return closeLanes(live.and(t.compare(GT, 0)).and(t.compare(LT, tMax)));
    }

    /** Clears the blocked lanes in shadowLanes; returns whether any lane is still open. */
    private boolean closeLanes(VectorMask<Double> blocked) {
        VectorMask<Double> open = DoubleVector.fromArray(SPECIES, shadowLanes, 0).compare(NE, 0).andNot(blocked);
        DoubleVector.zero(SPECIES).blend(1.0, open).intoArray(shadowLanes, 0);
        return open.anyTrue();
    }

    /** TracerWorker.shadeMatte's sum over lights: adds E cos to the lanes the light reaches. */
    private void addLight(RenderScene s, int light) {
        VectorMask<Double> reaches = DoubleVector.fromArray(SPECIES, shadowLanes, 0).compare(NE, 0);
        DoubleVector scale = DoubleVector.fromArray(SPECIES, falloff, 0);
        DoubleVector cos = DoubleVector.fromArray(SPECIES, cosLight, 0);
        int j = 3 * light;
        DoubleVector r = DoubleVector.fromArray(SPECIES, sumR, 0);
        DoubleVector g = DoubleVector.fromArray(SPECIES, sumG, 0);
        DoubleVector b = DoubleVector.fromArray(SPECIES, sumB, 0);
        r.blend(r.add(scale.mul(s.lightPower[j]).mul(cos)), reaches).intoArray(sumR, 0);
        g.blend(g.add(scale.mul(s.lightPower[j + 1]).mul(cos)), reaches).intoArray(sumG, 0);
        b.blend(b.add(scale.mul(s.lightPower[j + 2]).mul(cos)), reaches).intoArray(sumB, 0);
    }

    /** TracerWorker.shadeMatte's result: color x (sum / pi + ambient), into the radiance arrays. */
    private void writeMatte(RenderScene s, int material, int first,
                            double[] radianceR, double[] radianceG, double[] radianceB) {
        int c = 3 * material;
        DoubleVector.fromArray(SPECIES, sumR, 0).mul(INV_PI).add(s.ambientR).mul(s.materialColor[c])
                .intoArray(radianceR, first);
        DoubleVector.fromArray(SPECIES, sumG, 0).mul(INV_PI).add(s.ambientG).mul(s.materialColor[c + 1])
                .intoArray(radianceG, first);
        DoubleVector.fromArray(SPECIES, sumB, 0).mul(INV_PI).add(s.ambientB).mul(s.materialColor[c + 2])
                .intoArray(radianceB, first);
    }
}
