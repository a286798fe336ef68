package glint.render;

import glint.config.Shading;

/**
 * One render thread's tracer and scratch state: traces the pixels of the tiles it is handed. A
 * tile row's camera rays go in stages ({@link #traceInStages}: all aimed, all hits, each hit's
 * surface and shading, then the matte hits lit together); reflected and refracted rays, and every
 * ray of the phong model, go by recursion ({@link #trace}). Everything it writes between calls
 * lives in its own fields, so the per-pixel path allocates nothing. All vectors are world space;
 * directions are unit length.
 */
final class TracerWorker {

    private static final double INV_PI = 1 / Math.PI;
    /** {@code skipSurface} of a camera ray: it starts at the eye (no surface is skipped). */
    private static final int EYE = Integer.MIN_VALUE;

    private RenderScene scene;

    // the scene's settings, read once per tile rather than through the record on every ray
    private int recursionMax;
    private double epsilon;
    private double minWeight;
    private boolean phong;
    private boolean exactFresnel;

    private final RayCaster caster = new RayCaster();

    // radiance returned by trace()
    private double outR, outG, outB;

    // light sample of lightAt(): unit direction to the light, irradiance on a facing surface, distance
    private double toLightX, toLightY, toLightZ;
    private double irradianceR, irradianceG, irradianceB;
    private double lightDistance;

    // the direction Optics.refract writes
    private final double[] refracted = new double[3];

    /** The current tile row's camera rays and their radiance. */
    private final CameraRows rows = new CameraRows();
    /** The image x of the current row's first pixel, and the camera rays each pixel of it gets. */
    private int rowX0, raysPerPixel;

    /** The current tile row's hits, for tracing it in stages. */
    private final RowHits hits = new RowHits();
    /** Whether cook-torrance rows are traced in stages (the fast path) rather than ray by ray. */
    private final boolean stages;

    /** A worker that traces rows in stages, or, for comparison in tests, ray by ray. */
    TracerWorker(boolean stages) {
        this.stages = stages;
    }

    /** Traces camera rays four at a time where the Vector API is loaded; null where it is not. */
    private final CameraPackets packets = CameraPackets.load();

    /** Rays this worker has cast (camera, reflected, refracted and shadow rays). */
    long raysCast() {
        return caster.rays;
    }

    /**
     * Renders pixels [x0, x1) x [y0, y1): each pixel gets the average of samples
     * [firstSample, firstSample + sampleCount) of its {@code samples}-sample stratified pattern.
     */
    void renderTile(RenderScene renderScene, FrameBuffer frame, int samples, int firstSample, int sampleCount,
                    int frameIndex, int x0, int y0, int x1, int y1) {
        this.scene = renderScene;
        RenderSettings settings = renderScene.settings;
        recursionMax = settings.recursionMax();
        epsilon = settings.epsilon();
        minWeight = settings.minWeight();
        phong = settings.shading() == Shading.PHONG;
        exactFresnel = settings.glassFresnel() == RenderSettings.GlassFresnel.EXACT;
        int rowRays = (x1 - x0) * sampleCount;
        rows.prepare(renderScene.camera, frame.width(), frame.height(), x0, x1, samples, firstSample, sampleCount,
                frameIndex);
        rowX0 = x0;
        raysPerPixel = sampleCount;
        EyeRays eye = caster.eye;
        eye.prepare(renderScene);
        // screen y grows upwards, image y downwards
        eye.aimTile(rows.screenX(x0), rows.screenX(x1), rows.screenY(y1), rows.screenY(y0));
        boolean inPackets = packets != null && settings.simd() && packets.handles(renderScene);
        boolean inStages = stages && !phong;
        for (int y = y0; y < y1; y++) {
            eye.aimRow(rows.screenY(y + 1), rows.screenY(y));
            rows.aim(y);
            if (inPackets) {
                traceInPackets(rowRays);
            } else if (inStages) {
                traceInStages(rowRays);
            } else {
                traceOneByOne(0, rowRays);
            }
            rows.writeRow(frame, y);
        }
    }

    /**
     * Traces the row's camera rays [0, rays) four at a time through {@link #packets}, one by one
     * where a packet does not stay together.
     */
    private void traceInPackets(int rays) {
        CameraRows r = rows;
        int ray = 0;
        for (; ray + CameraPackets.LANES <= rays; ray += CameraPackets.LANES) {
            if (!packets.trace(scene, caster, r.dirX, r.dirY, r.dirZ, ray, r.radianceR, r.radianceG, r.radianceB)) {
                traceOneByOne(ray, ray + CameraPackets.LANES);
            }
        }
        traceOneByOne(ray, rays);
    }

    /**
     * Traces the row's camera rays [0, rays) in stages, into the row's radiance: every ray's nearest
     * hit, then every hit's surface and shading, with the matte hits set aside and then lit
     * together. Each pixel gets the same arithmetic in the same order as {@link #trace}, so the
     * image is the same bit for bit.
     */
    private void traceInStages(int rays) {
        hits.fit(rays);
        findHitsFromEye(rays);
        shadeRowHits(rays);
        lightMatteHits();
    }

    /**
     * Stage 1: the nearest hit of each camera ray of the row: sphere by sphere where that takes no
     * more sphere tests a ray, on average over the row, than a camera ray makes one by one before
     * the hierarchy pays, otherwise pixel by pixel, swept left to right as in
     * {@link #traceOneByOne}.
     */
    private void findHitsFromEye(int rays) {
        EyeRays eye = caster.eye;
        long tests = hits.planSphereBySphere(eye, rows, rowX0, raysPerPixel, rays);
        if (scene.bvh == null || tests <= (long) RayCaster.MOST_SPHERES_SWEPT * rays) {
            hits.findFromEyeSphereBySphere(scene, eye, rows, rays);
            caster.rays += rays;
            return;
        }
        for (int pixel = 0, ray = 0; ray < rays; pixel++) {
            eye.aimPixel(rows.screenX(rowX0 + pixel), rows.screenX(rowX0 + pixel + 1));
            for (int end = ray + raysPerPixel; ray < end; ray++) {
                findHitFromEye(ray);
            }
        }
    }

    private void findHitFromEye(int ray) {
        CameraRows r = rows;
        hits.storeHit(ray, caster, caster.nearestFromEye(scene, r.dirX[ray], r.dirY[ray], r.dirZ[ray]));
    }

    /**
     * Stage 2: the background for misses, and the surface at each matte hit, kept in the row's
     * matte slots for stage 3; then the metal and glass hits, their surfaces found and shaded one
     * by one (their reflected and refracted rays traced from there). The second kind waits for a
     * loop of its own: a call the JIT does not inline, left in the first loop, would make it keep
     * its values on the stack for every hit rather than in registers (docs/benchmarks.md).
     */
    private void shadeRowHits(int rays) {
        RowHits h = hits;
        CameraRows r = rows;
        RenderScene s = scene;
        CameraBasis camera = s.camera;
        int matte = 0, traced = 0;
        for (int ray = 0; ray < rays; ray++) {
            int sphere = h.sphere[ray], plane = h.plane[ray];
            if (sphere < 0 && plane < 0) {
                r.radianceR[ray] = s.backgroundR;
                r.radianceG[ray] = s.backgroundG;
                r.radianceB[ray] = s.backgroundB;
            } else if (s.materialType[sphere >= 0 ? s.sphereMaterial[sphere] : s.planeMaterial[plane]]
                    != RenderScene.MATTE) {
                h.tracedRays[traced++] = ray;
            } else {
                describeHit(h.t[ray], sphere, plane, camera.eyeX, camera.eyeY, camera.eyeZ, r.dirX[ray], r.dirY[ray],
                        r.dirZ[ray]);
                keepMatteHit(matte++, ray, RayCaster.skipNear(sphere, plane, hitEntering));
            }
        }
        h.matteCount = matte;
        for (int j = 0; j < traced; j++) {
            shadeTracedHit(h.tracedRays[j]);
        }
    }

    /** The shading of camera ray {@code ray}'s metal or glass hit, into the row's radiance. */
    private void shadeTracedHit(int ray) {
        RowHits h = hits;
        CameraRows r = rows;
        CameraBasis camera = scene.camera;
        int sphere = h.sphere[ray], plane = h.plane[ray];
        double dx = r.dirX[ray], dy = r.dirY[ray], dz = r.dirZ[ray];
        describeHit(h.t[ray], sphere, plane, camera.eyeX, camera.eyeY, camera.eyeZ, dx, dy, dz);
        int m = hitMaterial;
        int skipNear = RayCaster.skipNear(sphere, plane, hitEntering);
        if (scene.materialType[m] == RenderScene.METAL) {
            shadeMetal(m, dx, dy, dz, recursionMax, 1, skipNear);
        } else {
            shadeGlass(m, dx, dy, dz, recursionMax, 1, skipNear, RayCaster.skipFar(sphere, plane, hitEntering));
        }
        r.radianceR[ray] = outR;
        r.radianceG[ray] = outG;
        r.radianceB[ray] = outB;
    }

    /** Stores the matte surface describeHit() found for camera ray {@code ray} in matte slot j. */
    private void keepMatteHit(int j, int ray, int skipNear) {
        RowHits h = hits;
        h.matteRays[j] = ray;
        h.px[j] = hitX;
        h.py[j] = hitY;
        h.pz[j] = hitZ;
        h.nx[j] = normalX;
        h.ny[j] = normalY;
        h.nz[j] = normalZ;
        h.offset[j] = hitOffset;
        h.skipNear[j] = skipNear;
        h.material[j] = hitMaterial;
    }

    /**
     * Stage 3: the matte hits of the row, lit as {@link #shadeMatte} lights one: light by light,
     * first every hit's light sample, then every hit's shadow ray, each adding in light order.
     */
    private void lightMatteHits() {
        RowHits h = hits;
        RenderScene s = scene;
        int count = h.matteCount;
        for (int j = 0; j < count; j++) {
            h.sumR[j] = 0;
            h.sumG[j] = 0;
            h.sumB[j] = 0;
        }
        for (int light = 0; light < s.lightCount; light++) {
            sampleLight(light, count);
            addUnshadowed(light, count);
        }
        CameraRows r = rows;
        for (int j = 0; j < count; j++) {
            int ray = h.matteRays[j];
            int c = 3 * h.material[j];
            r.radianceR[ray] = lambert(s.materialColor[c], h.sumR[j], s.ambientR);
            r.radianceG[ray] = lambert(s.materialColor[c + 1], h.sumG[j], s.ambientG);
            r.radianceB[ray] = lambert(s.materialColor[c + 2], h.sumB[j], s.ambientB);
        }
    }

    /** The sample of light {@code light} at each matte hit, as {@link #lightAt} takes it. */
    private void sampleLight(int light, int count) {
        RenderScene s = scene;
        int k = 3 * light;
        double[] v = s.lightVector, power = s.lightPower;
        if (s.lightIsPoint[light]) {
            hits.samplePointLight(count, v[k], v[k + 1], v[k + 2], power[k], power[k + 1], power[k + 2]);
        } else {
            hits.sampleDirectionalLight(count, v[k], v[k + 1], v[k + 2], power[k], power[k + 1], power[k + 2]);
        }
    }

    /**
     * Adds light {@code light} at each matte hit that faces it and sees it: first the hits no sphere
     * can shadow, which need only the planes tested, then those a sphere may shadow, which take the
     * whole test. Where the light has cones, the row's cone margins, worked out first in SIMD, rule
     * out most hits without a cone tested one by one. The first loop has no call the JIT would not
     * inline; left in it, such a call would make it keep its values on the stack for every hit
     * rather than in registers.
     */
    private void addUnshadowed(int light, int count) {
        RowHits h = hits;
        RenderScene s = scene;
        RayCaster shadows = caster;
        LightCones cones = s.lightCones[light];
        double conesReach = Double.NEGATIVE_INFINITY; // hits offset no further than this may use the margins
        if (cones != null) {
            h.coneMargins(count, cones);
            conesReach = cones.maxOffset;
        }
        double[] margin = h.coneMargin;
        int suspects = 0;
        for (int j = 0; j < count; j++) {
            if (!(h.cosLight[j] > 0)) {
                continue;
            }
            double dx = h.toLightX[j], dy = h.toLightY[j], dz = h.toLightZ[j], offset = h.offset[j];
            if ((offset > conesReach || margin[j] >= 0)
                    && shadows.sphereMayShadow(s, dx, dy, dz, light, offset, h.skipNear[j])) {
                h.suspects[suspects++] = j;
                continue;
            }
            if (RayCaster.noPlaneToTest(s, h.skipNear[j])) {
                shadows.rays++; // the shadow ray, which meets nothing
                addLight(j);
                continue;
            }
            double ox = h.px[j] + offset * h.nx[j], oy = h.py[j] + offset * h.ny[j], oz = h.pz[j] + offset * h.nz[j];
            if (!shadows.anyPlaneBefore(s, ox, oy, oz, dx, dy, dz, h.lightDistance[j], h.skipNear[j])) {
                addLight(j);
            }
        }
        for (int k = 0; k < suspects; k++) {
            int j = h.suspects[k];
            double offset = h.offset[j];
            double ox = h.px[j] + offset * h.nx[j], oy = h.py[j] + offset * h.ny[j], oz = h.pz[j] + offset * h.nz[j];
            if (!shadows.shadowed(s, ox, oy, oz, h.toLightX[j], h.toLightY[j], h.toLightZ[j], h.lightDistance[j],
                    h.skipNear[j], light, offset)) {
                addLight(j);
            }
        }
    }

    /** Adds the current light's sample at matte hit j to its sum. */
    private void addLight(int j) {
        RowHits h = hits;
        h.sumR[j] += h.lightR[j];
        h.sumG[j] += h.lightG[j];
        h.sumB[j] += h.lightB[j];
    }

    /**
     * Traces camera rays [first, end) of the row one at a time, into the row's radiance. Calls for
     * one row come left to right: the eye's sweep follows the pixels.
     */
    private void traceOneByOne(int first, int end) {
        if (caster.eye.rowCount == 0) {
            traceFromEye(first, end); // no sphere in the row: no pixel shows one
            return;
        }
        int pixel = first / raysPerPixel; // of the row
        for (int ray = first, pixelEnd = (pixel + 1) * raysPerPixel; ray < end; pixel++, pixelEnd += raysPerPixel) {
            caster.eye.aimPixel(rows.screenX(rowX0 + pixel), rows.screenX(rowX0 + pixel + 1));
            int stop = Math.min(end, pixelEnd);
            traceFromEye(ray, stop);
            ray = stop;
        }
    }

    /** Traces camera rays [first, end) of the row, after the eye's sweep has reached their pixels, into the row's radiance. */
    private void traceFromEye(int first, int end) {
        CameraRows r = rows;
        CameraBasis camera = scene.camera;
        for (int ray = first; ray < end; ray++) {
            trace(camera.eyeX, camera.eyeY, camera.eyeZ, r.dirX[ray], r.dirY[ray], r.dirZ[ray], recursionMax, 1, EYE);
            r.radianceR[ray] = outR;
            r.radianceG[ray] = outG;
            r.radianceB[ray] = outB;
        }
    }

    /**
     * Radiance arriving at the ray's origin along -d, into outR/G/B. {@code hitsLeft} is how many
     * surface hits this path may still shade; {@code weight} is the path's throughput so far.
     */
    void trace(double ox, double oy, double oz, double dx, double dy, double dz, int hitsLeft, double weight,
               int skipSurface) {
        RenderScene s = scene;
        RayCaster hit = caster;
        boolean found = skipSurface == EYE ? hit.nearestFromEye(s, dx, dy, dz)
                : hit.nearest(s, ox, oy, oz, dx, dy, dz, skipSurface);
        if (!found) {
            outR = s.backgroundR;
            outG = s.backgroundG;
            outB = s.backgroundB;
            return;
        }
        describeHit(hit.hitT, hit.hitSphere, hit.hitPlane, ox, oy, oz, dx, dy, dz);
        int material = hitMaterial;
        int skipNear = RayCaster.skipNear(hit.hitSphere, hit.hitPlane, hitEntering);
        int skipFar = RayCaster.skipFar(hit.hitSphere, hit.hitPlane, hitEntering);
        if (phong) {
            shadePhong(material, dx, dy, dz, hitsLeft, weight, skipNear, skipFar);
            return;
        }
        switch (s.materialType[material]) {
            case RenderScene.MATTE -> shadeMatte(material, skipNear);
            case RenderScene.METAL -> shadeMetal(material, dx, dy, dz, hitsLeft, weight, skipNear);
            default -> shadeGlass(material, dx, dy, dz, hitsLeft, weight, skipNear, skipFar);
        }
    }

    // the surface describeHit() found: point, facing normal, cosine of incidence, offset, material.
    // The shade methods read it on entry, before any ray they trace overwrites it: a dozen values
    // a call fewer to pass on the stack.
    private double hitX, hitY, hitZ, normalX, normalY, normalZ, hitCosIncident, hitOffset;
    private boolean hitEntering;
    private int hitMaterial;

    /**
     * Works out the surface a ray from o along unit d meets at distance t (sphere or plane, the
     * other -1): the hit point moved onto the surface, the normal turned to face the ray, the
     * cosine of incidence, the offset for rays leaving it, whether the ray met its front side,
     * and its material.
     */
    private void describeHit(double t, int sphere, int plane, double ox, double oy, double oz,
                             double dx, double dy, double dz) {
        double px = ox + t * dx, py = oy + t * dy, pz = oz + t * dz;
        // the offset scales with |p|, taken before p is refined: the refinement moves p by far less
        // than a rounding step of the scale, and this way the square root runs alongside the
        // normal's rather than after it
        hitOffset = offsetAt(px, py, pz);
        if (sphere >= 0) {
            onSphere(sphere, px, py, pz);
        } else {
            onPlane(plane, px, py, pz);
        }
        faceTheRay(dx, dy, dz);
    }

    /** The point of sphere i nearest p (p re-projected onto it: removes the error t carries into p), its outward normal and material. */
    private void onSphere(int i, double px, double py, double pz) {
        RenderScene s = scene;
        int k = 4 * i;
        double cx = s.spheres[k], cy = s.spheres[k + 1], cz = s.spheres[k + 2], radius = s.spheres[k + 3];
        double ex = px - cx, ey = py - cy, ez = pz - cz;
        double inv = 1 / Math.sqrt(ex * ex + ey * ey + ez * ez);
        normalX = ex * inv;
        normalY = ey * inv;
        normalZ = ez * inv;
        hitX = cx + radius * normalX;
        hitY = cy + radius * normalY;
        hitZ = cz + radius * normalZ;
        hitMaterial = s.sphereMaterial[i];
    }

    /** The point of plane i nearest p, its normal and material. */
    private void onPlane(int i, double px, double py, double pz) {
        RenderScene s = scene;
        int k = 4 * i;
        double nx = s.planes[k], ny = s.planes[k + 1], nz = s.planes[k + 2];
        double off = nx * px + ny * py + nz * pz - s.planes[k + 3];
        hitX = px - off * nx;
        hitY = py - off * ny;
        hitZ = pz - off * nz;
        normalX = nx;
        normalY = ny;
        normalZ = nz;
        hitMaterial = s.planeMaterial[i];
    }

    /** Turns the normal to face the side the ray along d came from; sets the cosine of incidence and whether that is the front. */
    private void faceTheRay(double dx, double dy, double dz) {
        double cosIncident = -(dx * normalX + dy * normalY + dz * normalZ); // > 0 when the ray meets the front side
        hitEntering = cosIncident >= 0;
        if (!hitEntering) {
            normalX = -normalX;
            normalY = -normalY;
            normalZ = -normalZ;
            cosIncident = -cosIncident;
        }
        hitCosIncident = cosIncident;
    }

    // ---- cook-torrance ------------------------------------------------------------------------

    /** Lambert: color / pi x E x cos for each unshadowed light, plus ambient x color. */
    private void shadeMatte(int m, int skipNear) {
        RenderScene s = scene;
        double px = hitX, py = hitY, pz = hitZ, nx = normalX, ny = normalY, nz = normalZ, offset = hitOffset;
        double sumR = 0, sumG = 0, sumB = 0;
        double ox = px + offset * nx, oy = py + offset * ny, oz = pz + offset * nz;
        for (int light = 0; light < s.lightCount; light++) {
            double cosLight = lightAt(light, px, py, pz, nx, ny, nz);
            if (cosLight > 0 && !caster.shadowed(s, ox, oy, oz, toLightX, toLightY, toLightZ, lightDistance, skipNear,
                    light, offset)) {
                sumR += irradianceR * cosLight;
                sumG += irradianceG * cosLight;
                sumB += irradianceB * cosLight;
            }
        }
        int c = 3 * m;
        outR = lambert(s.materialColor[c], sumR, s.ambientR);
        outG = lambert(s.materialColor[c + 1], sumG, s.ambientG);
        outB = lambert(s.materialColor[c + 2], sumB, s.ambientB);
    }

    /**
     * One channel of a Lambert surface's radiance: color / pi x the irradiance summed over the lights
     * it sees (n.l applied), plus ambient x color.
     */
    private static double lambert(double color, double irradiance, double ambient) {
        return color * (irradiance * INV_PI + ambient);
    }

    /** A mirror weighted by Schlick's Fresnel (F0 = color), plus a GGX highlight when rough. */
    private void shadeMetal(int m, double dx, double dy, double dz, int hitsLeft, double weight, int skipNear) {
        RenderScene s = scene;
        double px = hitX, py = hitY, pz = hitZ, nx = normalX, ny = normalY, nz = normalZ;
        double cosView = hitCosIncident, offset = hitOffset;
        int c = 3 * m;
        double f0R = s.materialColor[c], f0G = s.materialColor[c + 1], f0B = s.materialColor[c + 2];
        double ox = px + offset * nx, oy = py + offset * ny, oz = pz + offset * nz;
        double sumR = 0, sumG = 0, sumB = 0;
        double alpha = s.alpha[m];
        if (alpha > 0 && cosView > 0) {
            for (int light = 0; light < s.lightCount; light++) {
                double cosLight = lightAt(light, px, py, pz, nx, ny, nz);
                if (cosLight <= 0 || caster.shadowed(s, ox, oy, oz, toLightX, toLightY, toLightZ, lightDistance,
                        skipNear, light, offset)) {
                    continue;
                }
                double hx = toLightX - dx, hy = toLightY - dy, hz = toLightZ - dz;
                double inv = 1 / Math.sqrt(hx * hx + hy * hy + hz * hz);
                double cosHalf = (hx * nx + hy * ny + hz * nz) * inv;
                double cosViewHalf = Math.max(0, -(hx * dx + hy * dy + hz * dz) * inv);
                double specular = Optics.ggx(cosHalf, alpha) * Optics.smithVisibility(cosLight, cosView, alpha) * cosLight;
                sumR += specular * Optics.schlick(f0R, cosViewHalf) * irradianceR;
                sumG += specular * Optics.schlick(f0G, cosViewHalf) * irradianceG;
                sumB += specular * Optics.schlick(f0B, cosViewHalf) * irradianceB;
            }
        }
        if (hitsLeft > 1) {
            double fR = Optics.schlick(f0R, cosView), fG = Optics.schlick(f0G, cosView), fB = Optics.schlick(f0B, cosView);
            double childWeight = weight * Math.max(fR, Math.max(fG, fB));
            if (childWeight >= minWeight) {
                double k = 2 * cosView;
                trace(ox, oy, oz, dx + k * nx, dy + k * ny, dz + k * nz, hitsLeft - 1, childWeight, skipNear);
                sumR += fR * outR;
                sumG += fG * outG;
                sumB += fB * outB;
            }
        }
        outR = sumR;
        outG = sumG;
        outB = sumB;
    }

    /** A smooth dielectric: reflection and refraction weighted by the exact Fresnel equations. */
    private void shadeGlass(int m, double dx, double dy, double dz, int hitsLeft, double weight, int skipNear,
                            int skipFar) {
        RenderScene s = scene;
        double px = hitX, py = hitY, pz = hitZ, nx = normalX, ny = normalY, nz = normalZ;
        double cosIncident = hitCosIncident, offset = hitOffset;
        boolean entering = hitEntering;
        double sumR = 0, sumG = 0, sumB = 0;
        if (hitsLeft > 1) {
            double eta = entering ? 1 / s.ior[m] : s.ior[m];
            double reflectance = glassReflectance(cosIncident, eta);
            if (weight * reflectance >= minWeight) {
                double k = 2 * cosIncident;
                trace(px + offset * nx, py + offset * ny, pz + offset * nz,
                        dx + k * nx, dy + k * ny, dz + k * nz, hitsLeft - 1, weight * reflectance, skipNear);
                sumR += reflectance * outR;
                sumG += reflectance * outG;
                sumB += reflectance * outB;
            }
            int c = 3 * m;
            double tR = (1 - reflectance) * s.materialColor[c];
            double tG = (1 - reflectance) * s.materialColor[c + 1];
            double tB = (1 - reflectance) * s.materialColor[c + 2];
            double childWeight = weight * Math.max(tR, Math.max(tG, tB));
            if (reflectance < 1 && childWeight >= minWeight) {
                int entered = RayCaster.sphereInside(skipFar);
                if (entered >= 0 && s.sphereIsEmpty[entered]
                        && Optics.refract(dx, dy, dz, nx, ny, nz, cosIncident, eta, refracted)) {
                    traceInsideEmptySphere(entered, m, px, py, pz, nx, ny, nz, cosIncident, hitsLeft - 1, childWeight);
                } else {
                    traceRefracted(px, py, pz, nx, ny, nz, dx, dy, dz, cosIncident, eta, offset, hitsLeft,
                            childWeight, skipNear, skipFar);
                }
                sumR += tR * outR;
                sumG += tG * outG;
                sumB += tB * outB;
            }
        }
        outR = sumR;
        outG = sumG;
        outB = sumB;
    }

    /**
     * Traces the refracted ray through the boundary (n faces the incident side, eta = n_incident /
     * n_transmitted), its origin offset to the far side; past the critical angle, the reflected one.
     */
    private void traceRefracted(double px, double py, double pz, double nx, double ny, double nz,
                                double dx, double dy, double dz, double cosIncident, double eta, double offset,
                                int hitsLeft, double weight, int skipNear, int skipFar) {
        double[] t = refracted;
        if (Optics.refract(dx, dy, dz, nx, ny, nz, cosIncident, eta, t)) {
            trace(px - offset * nx, py - offset * ny, pz - offset * nz, t[0], t[1], t[2], hitsLeft - 1, weight, skipFar);
        } else {
            double k = 2 * cosIncident;
            trace(px + offset * nx, py + offset * ny, pz + offset * nz,
                    dx + k * nx, dy + k * ny, dz + k * nz, hitsLeft - 1, weight, skipNear);
        }
    }

    /**
     * The radiance brought back by the ray refracted into empty glass sphere i at p (on the sphere;
     * n the outward normal, {@code cosOutside} the cosine of incidence there, the refracted unit
     * direction in {@link #refracted}), as {@link #trace} would find it, but without a search or a
     * Fresnel evaluation per bounce. Nothing else reaches into the sphere, so the ray bounces inside
     * it, and at each bounce a ray leaves it and the rest reflects on. Both ends of a chord meet the
     * sphere at the same angle, so every bounce meets it at the refracted ray's angle: each chord is
     * 2 r cos(theta) long, every bounce reflects the same fraction, and every ray that leaves bends
     * back to the incident angle. {@code hitsLeft} and {@code weight} are the refracted ray's.
     */
    private void traceInsideEmptySphere(int i, int m, double px, double py, double pz, double nx, double ny,
                                        double nz, double cosOutside, int hitsLeft, double weight) {
        double ux = refracted[0], uy = refracted[1], uz = refracted[2]; // the ray inside, unit
        double cosInside = -(ux * nx + uy * ny + uz * nz);
        RenderScene s = scene;
        int k = 4 * i;
        double cx = s.spheres[k], cy = s.spheres[k + 1], cz = s.spheres[k + 2], radius = s.spheres[k + 3];
        double chord = 2 * radius * cosInside, inverseRadius = 1 / radius;
        double ior = s.ior[m];
        double reflectance = glassReflectance(cosInside, ior);
        int c = 3 * m;
        double tR = (1 - reflectance) * s.materialColor[c];
        double tG = (1 - reflectance) * s.materialColor[c + 1];
        double tB = (1 - reflectance) * s.materialColor[c + 2];
        double transmitted = Math.max(tR, Math.max(tG, tB));
        double bend = ior * cosInside - cosOutside; // refraction out: ior u + bend (-n)
        int leaving = RayCaster.surfaceId(i, -1);
        double sumR = 0, sumG = 0, sumB = 0, reflectedSoFar = 1; // the product of the bounces' reflectances
        for (; ; hitsLeft--) {
            caster.rays++; // the chord, found without a search
            if (hitsLeft <= 1) {
                break; // glass with no hits left returns nothing
            }
            double qx = px + chord * ux, qy = py + chord * uy, qz = pz + chord * uz; // the chord's end
            double outwardX = (qx - cx) * inverseRadius, outwardY = (qy - cy) * inverseRadius,
                    outwardZ = (qz - cz) * inverseRadius;
            if (reflectance < 1 && weight * transmitted >= minWeight) {
                double offset = offsetAt(qx, qy, qz);
                double lx = ior * ux - bend * outwardX, ly = ior * uy - bend * outwardY, lz = ior * uz - bend * outwardZ;
                double inv = 1 / Math.sqrt(lx * lx + ly * ly + lz * lz);
                trace(qx + offset * outwardX, qy + offset * outwardY, qz + offset * outwardZ, lx * inv, ly * inv,
                        lz * inv, hitsLeft - 1, weight * transmitted, leaving);
                sumR += reflectedSoFar * tR * outR;
                sumG += reflectedSoFar * tG * outG;
                sumB += reflectedSoFar * tB * outB;
            }
            if (!(weight * reflectance >= minWeight)) {
                break;
            }
            reflectedSoFar *= reflectance;
            weight *= reflectance;
            double twiceCos = 2 * cosInside; // the reflection inside: u - 2 (u.n) n, u.n = cos(theta)
            ux -= twiceCos * outwardX;
            uy -= twiceCos * outwardY;
            uz -= twiceCos * outwardZ;
            px = qx;
            py = qy;
            pz = qz;
        }
        outR = sumR;
        outG = sumG;
        outB = sumB;
    }

    // ---- phong --------------------------------------------------------------------------------

    /**
     * The seed's model: ka ambient color + sum over lights (kd color E n.l + ks E (r.v)^shininess)
     * + ks I_reflected + kt color I_transmitted, with ka = kd. Glass occluders pass kt of the light.
     */
    private void shadePhong(int m, double dx, double dy, double dz, int hitsLeft, double weight, int skipNear,
                            int skipFar) {
        RenderScene s = scene;
        double px = hitX, py = hitY, pz = hitZ, nx = normalX, ny = normalY, nz = normalZ;
        double cosIncident = hitCosIncident, offset = hitOffset;
        boolean entering = hitEntering;
        int c = 3 * m;
        double colorR = s.materialColor[c], colorG = s.materialColor[c + 1], colorB = s.materialColor[c + 2];
        double kd = s.kd[m], ks = s.ks[m], kt = s.kt[m];
        double ox = px + offset * nx, oy = py + offset * ny, oz = pz + offset * nz;
        double diffuseR = s.ambientR, diffuseG = s.ambientG, diffuseB = s.ambientB;
        double specR = 0, specG = 0, specB = 0;
        for (int light = 0; light < s.lightCount; light++) {
            double cosLight = lightAt(light, px, py, pz, nx, ny, nz);
            if (cosLight <= 0) {
                continue;
            }
            double pass = caster.transmittance(s, ox, oy, oz, toLightX, toLightY, toLightZ, lightDistance, skipNear);
            if (pass == 0) {
                continue;
            }
            diffuseR += pass * irradianceR * cosLight;
            diffuseG += pass * irradianceG * cosLight;
            diffuseB += pass * irradianceB * cosLight;
            // r = reflection of the light direction about n; v = -d
            double k = 2 * cosLight;
            double cosReflectView = -((k * nx - toLightX) * dx + (k * ny - toLightY) * dy + (k * nz - toLightZ) * dz);
            if (cosReflectView > 0) {
                double highlight = pass * Math.pow(cosReflectView, s.shininess[m]);
                specR += highlight * irradianceR;
                specG += highlight * irradianceG;
                specB += highlight * irradianceB;
            }
        }
        double sumR = kd * colorR * diffuseR + ks * specR;
        double sumG = kd * colorG * diffuseG + ks * specG;
        double sumB = kd * colorB * diffuseB + ks * specB;
        if (hitsLeft > 1) {
            double k = 2 * cosIncident;
            double rx = dx + k * nx, ry = dy + k * ny, rz = dz + k * nz;
            if (weight * ks >= minWeight) {
                trace(ox, oy, oz, rx, ry, rz, hitsLeft - 1, weight * ks, skipNear);
                sumR += ks * outR;
                sumG += ks * outG;
                sumB += ks * outB;
            }
            double childWeight = weight * kt * Math.max(colorR, Math.max(colorG, colorB));
            if (childWeight >= minWeight && childWeight > 0) {
                double eta = entering ? 1 / s.ior[m] : s.ior[m];
                traceRefracted(px, py, pz, nx, ny, nz, dx, dy, dz, cosIncident, eta, offset, hitsLeft, childWeight,
                        skipNear, skipFar);
                sumR += kt * colorR * outR;
                sumG += kt * colorG * outG;
                sumB += kt * colorB * outB;
            }
        }
        outR = sumR;
        outG = sumG;
        outB = sumB;
    }

    /** The offset of rays leaving point p: epsilon scaled by max(1, |p|). */
    private double offsetAt(double px, double py, double pz) {
        return epsilon * atLeastOne(Math.sqrt(px * px + py * py + pz * pz));
    }

    /** The fraction a smooth glass boundary reflects, by the configured Fresnel model (eta = n_incident / n_transmitted). */
    private double glassReflectance(double cosIncident, double eta) {
        return exactFresnel ? Optics.fresnelDielectric(cosIncident, eta) : Optics.schlickDielectric(cosIncident, eta);
    }

    /**
     * max(1, distance) for a distance (>= 0, not NaN): one comparison, where Math.max's handling of
     * NaN and -0 costs a blend sequence on the path from the hit point to the spawned rays.
     */
    private static double atLeastOne(double distance) {
        return distance > 1 ? distance : 1;
    }

    // ---- lights and visibility ----------------------------------------------------------------

    /**
     * Samples light {@code i} from surface point o: sets toLight, irradiance on a surface facing the
     * light and lightDistance; returns n.l (the cosine at a surface of normal n). Taken from the
     * surface point itself rather than the offset shadow-ray origin (they differ by epsilon |p|), so
     * that it need not wait for the offset. {@link RowHits#samplePointLight} and
     * {@link RowHits#sampleDirectionalLight} do the same arithmetic for a row's matte hits at once.
     */
    private double lightAt(int i, double ox, double oy, double oz, double nx, double ny, double nz) {
        RenderScene s = scene;
        int j = 3 * i;
        double scale;
        if (s.lightIsPoint[i]) {
            double lx = s.lightVector[j] - ox, ly = s.lightVector[j + 1] - oy, lz = s.lightVector[j + 2] - oz;
            double distance2 = lx * lx + ly * ly + lz * lz;
            if (distance2 == 0) {
                return 0;
            }
            double inv = 1 / Math.sqrt(distance2);
            lightDistance = distance2 * inv;
            toLightX = lx * inv;
            toLightY = ly * inv;
            toLightZ = lz * inv;
            scale = inv * inv;
        } else {
            toLightX = s.lightVector[j];
            toLightY = s.lightVector[j + 1];
            toLightZ = s.lightVector[j + 2];
            lightDistance = Double.POSITIVE_INFINITY;
            scale = 1;
        }
        irradianceR = s.lightPower[j] * scale;
        irradianceG = s.lightPower[j + 1] * scale;
        irradianceB = s.lightPower[j + 2] * scale;
        return toLightX * nx + toLightY * ny + toLightZ * nz;
    }
}
