package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.accel.TraversalStack;
import glint.geometry.Hit;
import glint.geometry.Intersect;
import glint.image.FrameBuffer;
import glint.scene.Scene;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The bidirectional integrator checked as Veach's and pbrt's are: the strategies and the merges, each
 * weighted, sum to the full estimate; on random paths the weights of all the strategies that can make a
 * path, joins and merges, sum to 1;
 * the white furnace is 1; light tracing alone (strategy t = 1) gives the direct light next-event
 * estimation (s = 1) gives; and on scenes without caustic paths bdpt and path agree within their noise
 * (a z-test over blocks of pixels, each block's noise measured over independent frames).
 */
class BdptIntegratorTest {

    /** Matte, rough metal and frosted glass balls on a floor, a sphere lamp, a sun with a size and a sky. */
    static final String MIXED = """
            camera: {position: [0, 2.2, -4], look_at: [0, 0.5, 0.5], fov: 50}
            background: [0.3, 0.35, 0.45]
            lights:
              - {type: point, position: [1.5, 3, 0.2], radius: 0.3, intensity: 8}
              - {type: directional, direction: [-0.4, -1, 0.5], angle: 6, intensity: 0.8}
              - {type: point, position: [-2, 2, -1], intensity: 3}
            objects:
              - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.7, 0.7, 0.7]}}
              - {type: sphere, center: [-0.9, 0.5, 0.3], radius: 0.5, material: {type: matte, color: [0.8, 0.3, 0.2]}}
              - {type: sphere, center: [0.2, 0.5, 1.0], radius: 0.5, material: {type: metal, color: [0.9, 0.8, 0.6], roughness: 0.3}}
              - {type: sphere, center: [1.0, 0.45, 0.0], radius: 0.45, material: {type: glass, ior: 1.5, roughness: 0.3}}
            """;

    /** Matte only, a sphere lamp and a point light, no sky: no caustic path. */
    static final String MATTE = """
            camera: {position: [0, 2.2, -4], look_at: [0, 0.5, 0.5], fov: 50}
            lights:
              - {type: point, position: [1.5, 3, 0.2], radius: 0.4, intensity: 10}
              - {type: point, position: [-2, 2, -1], intensity: 3}
            objects:
              - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.7, 0.7, 0.7]}}
              - {type: plane, point: [0, 0, 2], normal: [0, 0, -1], material: {type: matte, color: [0.6, 0.7, 0.6]}}
              - {type: sphere, center: [-0.9, 0.5, 0.3], radius: 0.5, material: {type: matte, color: [0.8, 0.3, 0.2]}}
              - {type: sphere, center: [0.6, 0.6, 0.6], radius: 0.6, material: {type: matte, color: [0.3, 0.5, 0.8]}}
            """;

    @Test
    void theStrategiesEachWeightedSumToTheFullEstimate() {
        int depth = 3, w = 24, h = 18, spp = 4;
        RenderScene scene = compile(MIXED, depth);
        FrameBuffer full = render(scene, w, h, spp, 0);
        double[] sum = new double[full.rgb().length];
        for (int length = 2; length <= depth + 2; length++) {
            for (int t = 1; t <= length; t++) {
                float[] part = render(scene.withStrategy(length - t, t, true), w, h, spp, 0).rgb();
                for (int i = 0; i < sum.length; i++) {
                    sum[i] += part[i];
                }
            }
        }
        float[] merges = render(scene.withStrategy(RenderScene.MERGES, RenderScene.MERGES, true), w, h, spp, 0).rgb();
        for (int i = 0; i < sum.length; i++) {
            sum[i] += merges[i];
        }
        double total = 0;
        for (int i = 0; i < sum.length; i++) {
            float expected = full.rgb()[i];
            assertEquals(expected, sum[i], 1e-5 * (1 + expected), "channel value " + i);
            total += expected;
        }
        assertTrue(total / sum.length > 0.05, "the scene is lit: " + total / sum.length);
    }

    /**
     * Camera paths that end at a light, of seeded random scenes' camera rays: each read backwards as the
     * light subpath it also is, and the weight of every strategy the integrator has that could make it
     * (both joined vertices not delta; a light point seen directly, s = t = 1, left out) summed: 1, to
     * within the rounding of densities worked out along the path in either direction.
     */
    @Test
    void theWeightsOfEveryStrategyOfARandomPathSumToOne() {
        SplittableRandom random = new SplittableRandom(11);
        int checked = 0, longest = 0, chains = 0;
        for (int sceneNumber = 0; sceneNumber < 6; sceneNumber++) {
            RenderScene scene = compile(randomScene(random), 6);
            BdptIntegrator bdpt = new BdptIntegrator();
            bdpt.prepare(scene);
            Splats splats = new Splats();
            splats.clear(32, 24);
            bdpt.splatInto(splats);
            LightVertices pass = new LightVertices(); // one light subpath, which every camera path joins
            pass.begin(1, 0);
            bdpt.pass(pass);
            bdpt.traceLightPaths(pass.chunk(0), 0, 1, sceneNumber, 0, 1, 6);
            pass.finish();
            bdpt.weights.merging(1 << 16, 0.1); // merges about as likely as joins
            bdpt.weights.lightTracing(sceneNumber % 2 == 0 ? 1 : 0.3); // and light tracing, or less likely
            TraversalStack stack = scene.aggregate.newStack();
            double[] ox = new double[1], oy = new double[1], oz = new double[1];
            double[] dx = new double[1], dy = new double[1], dz = new double[1];
            Hit hit = new Hit();
            for (int ray = 0; ray < 4000; ray++) {
                scene.camera.ray(random.nextDouble(32), random.nextDouble(24), 0.5, 0.5, 32, 24, ox, oy, oz, dx, dy,
                        dz, 0);
                boolean found = scene.aggregate.nearest(ox[0], oy[0], oz[0], dx[0], dy[0], dz[0], Intersect.MISS,
                        Hit.NONE, Hit.NONE, hit, stack);
                bdpt.beginPath(ray, sceneNumber, 0, 1);
                bdpt.shadeCamera(found ? hit.primitive : Hit.NONE, found ? hit.t : Intersect.MISS, ox[0], oy[0], oz[0],
                        dx[0], dy[0], dz[0], 6);
                int n = bdpt.cameraVertices;
                BdptVertex end = bdpt.camera[n - 1];
                if (n < 3 || end.kind != BdptVertex.LIGHT && end.kind != BdptVertex.FAR) {
                    continue;
                }
                double sum = sumOfWeights(bdpt, n);
                assertEquals(1, sum, 1e-6, "path of " + n + " vertices, ray " + ray + " of scene " + sceneNumber);
                checked++;
                longest = Math.max(longest, n);
                for (int i = 1; i < n - 1; i++) {
                    chains += bdpt.camera[i].delta ? 1 : 0;
                }
            }
        }
        assertTrue(checked > 500, "paths checked: " + checked);
        assertTrue(longest >= 5, "longest path: " + longest);
        assertTrue(chains > 100, "delta vertices on the paths checked (smooth glass, mirrors): " + chains);
    }

    /** The sum over s of the weight of strategy (s, n - s) for the camera path of n vertices read both ways. */
    private static double sumOfWeights(BdptIntegrator bdpt, int n) {
        BdptWeights weights = bdpt.weights;
        BdptVertex[] camera = bdpt.camera;
        BdptVertex[] light = new BdptVertex[n];
        for (int i = 0; i < n - 1; i++) { // y_i is z_(n-1-i); the camera itself is never a light vertex
            BdptVertex z = camera[n - 1 - i], y = new BdptVertex();
            copy(z, y);
            y.pdfRev = z.pdfFwd;
            light[i] = y;
        }
        BdptVertex y0 = light[0];
        y0.pdfFwd = weights.pdfLightOrigin(y0);
        light[1].pdfFwd = light[1].delta ? BdptWeights.PAST_DELTA : weights.pdfLight(y0, light[1]);
        for (int i = 2; i < n - 1; i++) {
            light[i].pdfFwd = camera[n - 1 - i].pdfRev;
        }
        int chainEnd = 1;
        while (chainEnd < n - 1 && light[chainEnd].delta) { // the light's own chain of delta vertices ends here
            chainEnd++;
        }
        if (chainEnd > 1 && chainEnd < n - 1) {
            BdptVertex first = light[1], end = light[chainEnd];
            double ux = first.surface.px - y0.surface.px, uy = first.surface.py - y0.surface.py;
            double uz = first.surface.pz - y0.surface.pz;
            double inv = 1 / Math.sqrt(ux * ux + uy * uy + uz * uz);
            if (y0.kind == BdptVertex.FAR) {
                ux = -y0.farX;
                uy = -y0.farY;
                uz = -y0.farZ;
                inv = 1;
            }
            double pdf = weights.pdfToward(y0, null, first, ux * inv, uy * inv, uz * inv);
            BdptVertex last = camera[n - chainEnd]; // the chain's last delta vertex, on the camera's side
            double ix = last.surface.px - end.surface.px, iy = last.surface.py - end.surface.py;
            double iz = last.surface.pz - end.surface.pz;
            double inIn = 1 / Math.sqrt(ix * ix + iy * iy + iz * iz);
            end.pdfFwd = weights.throughChain(pdf, y0, ux * inv, uy * inv, uz * inv, end, ix * inIn, iy * inIn,
                    iz * inIn);
        }
        for (int i = 1; i < n - 1; i++) { // a light vertex's wo points back along the light subpath
            BdptVertex y = light[i], before = light[i - 1];
            double vx = before.kind == BdptVertex.FAR ? before.farX : before.surface.px - y.surface.px;
            double vy = before.kind == BdptVertex.FAR ? before.farY : before.surface.py - y.surface.py;
            double vz = before.kind == BdptVertex.FAR ? before.farZ : before.surface.pz - y.surface.pz;
            double inv = 1 / Math.sqrt(vx * vx + vy * vy + vz * vz);
            y.woX = vx * inv;
            y.woY = vy * inv;
            y.woZ = vz * inv;
        }
        BdptVertex sampledLight = new BdptVertex();
        copy(y0, sampledLight);
        sampledLight.pdfFwd = y0.pdfFwd;
        double sum = 0;
        for (int s = 0; s < n; s++) {
            int t = n - s;
            boolean made = s == 0 || (t == 1 || camera[t - 1].connectible) && (s == 1 || light[s - 1].connectible);
            if (made && !(s == 1 && t == 1)) {
                sum += weights.weight(s, t, camera, light, sampledLight, camera[0]);
            }
        }
        for (int i = 1; i < n - 1; i++) { // the light subpath up to camera[i] merged there with the camera's
            if (BdptWeights.merges(camera[i])) {
                sum += weights.mergeWeight(n - i, i + 1, camera, light);
            }
        }
        return sum;
    }

    private static void copy(BdptVertex from, BdptVertex to) {
        to.kind = from.kind;
        to.setPoint(from.surface.px, from.surface.py, from.surface.pz);
        to.setNormal(from.surface.nx, from.surface.ny, from.surface.nz);
        to.surface.front = from.surface.front;
        to.surface.material = from.surface.material;
        to.setFar(from.farX, from.farY, from.farZ);
        to.light = from.light;
        to.delta = from.delta;
        to.deltaLight = from.deltaLight;
        to.connectible = from.connectible;
        to.diffuse = from.diffuse;
    }

    /** A floor, matte and rough balls at random, a lamp and a sun with a size, a sky of random colour. */
    private static String randomScene(SplittableRandom random) {
        StringBuilder yaml = new StringBuilder("""
                camera: {position: [0, 2, -5], look_at: [0, 0.5, 0], fov: 55}
                """);
        yaml.append(String.format(java.util.Locale.ROOT, "background: [%.2f, %.2f, %.2f]%n", random.nextDouble(0.5),
                random.nextDouble(0.5), random.nextDouble(0.5)));
        yaml.append(String.format(java.util.Locale.ROOT, """
                lights:
                  - {type: point, position: [%.2f, 3, %.2f], radius: %.2f, intensity: 9}
                  - {type: directional, direction: [0.3, -1, 0.2], angle: %.1f, intensity: 1}
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.7, 0.7, 0.7]}}
                """, random.nextDouble(-2, 2), random.nextDouble(-1, 2), random.nextDouble(0.1, 0.6),
                random.nextDouble(1, 20)));
        String[] materials = {"{type: matte, color: [0.8, 0.6, 0.4]}", "{type: metal, color: [0.9, 0.9, 0.9], roughness: 0.4}",
                "{type: glass, ior: 1.5, roughness: 0.4}", "{type: matte, color: [0.3, 0.6, 0.9]}",
                "{type: glass, ior: 1.5}", "{type: metal, color: [0.9, 0.9, 0.9]}"};
        for (int i = 0; i < 5; i++) {
            double r = random.nextDouble(0.2, 0.7);
            yaml.append(String.format(java.util.Locale.ROOT,
                    "  - {type: sphere, center: [%.2f, %.2f, %.2f], radius: %.2f, material: %s}%n",
                    random.nextDouble(-2.5, 2.5), r, random.nextDouble(-1, 2.5), r, materials[random.nextInt(materials.length)]));
        }
        return yaml.toString();
    }

    /** White Lambert balls on a white floor under a sky of 1: every path's light is 1, so every pixel is 1. */
    @Test
    void theWhiteFurnaceIsOne() {
        String yaml = """
                camera: {position: [0, 1.5, -4], look_at: [0, 0.5, 0.5], fov: 50}
                background: [1, 1, 1]
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [1, 1, 1]}}
                  - {type: sphere, center: [-0.6, 0.5, 0.3], radius: 0.5, material: {type: matte, color: [1, 1, 1]}}
                  - {type: sphere, center: [0.7, 0.7, 0.8], radius: 0.7, material: {type: matte, color: [1, 1, 1]}}
                """;
        Blocks furnace = Blocks.of(compile(yaml, 64), 16, 12, 2, 16, 8);
        assertAgree(furnace, Blocks.constant(furnace.means.length, 1), "furnace");
        assertEquals(1, furnace.mean(), 0.005);
    }

    /**
     * Light tracing alone (s = 2, t = 1, unweighted) and next-event estimation alone (s = 1, t = 2) agree
     * on a floor and a wall under a sphere lamp, where light paths reach every pixel often.
     */
    @Test
    void lightTracingAloneGivesTheDirectLightOfAMatteScene() {
        String yaml = """
                camera: {position: [0, 1.5, -4], look_at: [0, 0.5, 0.5], fov: 50}
                lights:
                  - {type: point, position: [0.5, 2.5, 0], radius: 0.3, intensity: 10}
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.7, 0.7, 0.7]}}
                  - {type: plane, point: [0, 0, 2], normal: [0, 0, -1], material: {type: matte, color: [0.5, 0.6, 0.7]}}
                  - {type: sphere, center: [-0.4, 0.5, 0.6], radius: 0.5, material: {type: matte, color: [0.8, 0.3, 0.2]}}
                """;
        RenderScene scene = compile(yaml, 1);
        Blocks traced = Blocks.of(scene.withStrategy(2, 1, false), 24, 18, 3, 64, 8);
        Blocks sampled = Blocks.of(scene.withStrategy(1, 2, false), 24, 18, 3, 64, 8);
        assertAgree(traced, sampled, "light tracing against next-event estimation");
        assertEquals(sampled.mean(), traced.mean(), 0.01 * sampled.mean());
    }

    /** Without caustic paths the two unbiased integrators agree within their noise. */
    @Test
    void bdptAndPathAgreeWithinTheirNoiseWithoutCausticPaths() {
        RenderScene bdpt = compile(MATTE, 4);
        RenderScene path = RenderScene.compile(Renders.scene(MATTE),
                new RenderSettings(Shading.COOK_TORRANCE, 4, 0, Renders.EPSILON).withTransport(LightTransport.PATH));
        Blocks a = Blocks.of(bdpt, 24, 18, 2, 16, 8);
        Blocks b = Blocks.of(path, 24, 18, 2, 16, 8);
        assertAgree(a, b, "bdpt against path");
        assertEquals(b.mean(), a.mean(), 0.01 * b.mean());
    }

    /**
     * Two renders agree where each block's difference of means over its standard error (z, the noise
     * measured over independent frames) is beyond 4.5 in at most one value in 200 (at most one in all),
     * and the mean z over the image is within 0.3: a bias of the whole image shows there long before
     * single blocks do.
     */
    private static void assertAgree(Blocks a, Blocks b, String what) {
        int n = a.means.length, beyond = 0;
        double sumZ = 0;
        for (int i = 0; i < n; i++) {
            double error = Math.sqrt(a.variances[i] / a.count + b.variances[i] / b.count);
            double z = error > 0 ? (a.means[i] - b.means[i]) / error : a.means[i] == b.means[i] ? 0 : 99;
            sumZ += z;
            beyond += Math.abs(z) > 4.5 ? 1 : 0;
        }
        assertTrue(beyond <= Math.max(1, n / 200), what + ": " + beyond + " of " + n + " values with |z| > 4.5");
        assertEquals(0, sumZ / n, 0.3, what + ": mean z");
    }

    /**
     * Per channel of each block of size x size pixels, the mean and sample variance of its mean value over
     * independent frames (frame indices 0, 1, ...).
     */
    private record Blocks(double[] means, double[] variances, int count) {

        static Blocks of(RenderScene scene, int w, int h, int size, int spp, int frames) {
            int columns = w / size, rows = h / size;
            double[] sum = new double[3 * columns * rows], sum2 = new double[sum.length];
            for (int f = 0; f < frames; f++) {
                FrameBuffer frame = render(scene, w, h, spp, f);
                double[] block = new double[sum.length];
                for (int y = 0; y < rows * size; y++) {
                    for (int x = 0; x < columns * size; x++) {
                        for (int c = 0; c < 3; c++) {
                            block[3 * (y / size * columns + x / size) + c] += frame.get(x, y, c) / (size * size);
                        }
                    }
                }
                for (int i = 0; i < block.length; i++) {
                    sum[i] += block[i];
                    sum2[i] += block[i] * block[i];
                }
            }
            double[] mean = new double[sum.length], variance = new double[sum.length];
            for (int i = 0; i < sum.length; i++) {
                mean[i] = sum[i] / frames;
                variance[i] = Math.max(0, (sum2[i] - frames * mean[i] * mean[i]) / (frames - 1));
            }
            return new Blocks(mean, variance, frames);
        }

        static Blocks constant(int n, double value) {
            double[] mean = new double[n];
            java.util.Arrays.fill(mean, value);
            return new Blocks(mean, new double[n], 1);
        }

        double mean() {
            double s = 0;
            for (double m : means) {
                s += m;
            }
            return s / means.length;
        }
    }

    static RenderScene compile(String yaml, int depth) {
        Scene scene = Renders.scene(yaml);
        return RenderScene.compile(scene,
                new RenderSettings(Shading.COOK_TORRANCE, depth, 0, Renders.EPSILON).withTransport(LightTransport.BDPT));
    }

    static FrameBuffer render(RenderScene scene, int w, int h, int spp, int frameIndex) {
        FrameBuffer frame = new FrameBuffer(w, h);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(scene, frame, spp, frameIndex, 3);
        }
        return frame;
    }
}
