package glint.recipe;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import glint.registry.Registry;
import glint.render.Renders;
import org.junit.jupiter.api.Test;

/** The light recipe followed in test sources: a lamp without falloff read, compiled and rendered. */
class LightRecipeTest {

    private static final Registry REGISTRY = Registry.STANDARD.with(LampType.TYPE);

    /** A matte floor at y = -1 of albedo 0.5 under a lamp of intensity 3, a ball between them. */
    private static final String SCENE = """
            camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 60}
            lights:
              - {type: lamp, position: [0, 3, 6], intensity: 3}
            objects:
              - {type: plane, point: [0, -1, 0], normal: [0, 1, 0], material: {type: matte, color: [0.5, 0.5, 0.5]}}
              - {type: sphere, center: [0, 1, 6], radius: 0.5}
            """;
    private static final double[] LAMP = {0, 3, 6}, BALL = {0, 1, 6};
    private static final double BALL_RADIUS = 0.5;

    @Test
    void theFloorIsLitByCosineAloneWhateverItsDistanceAndShadowedBehindTheBall() {
        int w = 48, h = 36;
        FrameBuffer frame = Recipes.render(REGISTRY, SCENE, w, h, 1);
        int lit = 0, shadowed = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double[] d = Renders.axisCameraRay(60, w, h, x, y);
                if (d[1] >= 0 || segmentMissBy(new double[3], scale(d, 100)) < 0.02) {
                    continue; // the ray misses the floor, or meets the ball or nearly so
                }
                double[] p = scale(d, -1 / d[1]);
                double[] l = {LAMP[0] - p[0], LAMP[1] - p[1], LAMP[2] - p[2]};
                double cos = l[1] / Math.sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
                double miss = segmentMissBy(p, LAMP);
                if (Math.abs(miss) < 0.02) {
                    continue; // on the shadow's edge
                }
                double expected = miss < 0 ? 0 : 0.5 / Math.PI * 3 * cos;
                assertEquals(expected, frame.get(x, y, 1), 1e-6 * Math.max(1, expected), "pixel " + x + ", " + y);
                if (miss < 0) {
                    shadowed++;
                } else {
                    lit++;
                }
            }
        }
        assertTrue(lit > 100 && shadowed > 5, lit + " lit pixels, " + shadowed + " shadowed");
    }

    @Test
    void aLampIsReadWithTheLoadersChecksAndMessages() {
        assertEquals("recipe.yaml:2:5: missing required key 'position' in lamp light",
                Recipes.error(REGISTRY, "lights:\n  - {type: lamp, intensity: 2}\n"));
        assertEquals("recipe.yaml:2:12: unknown light type 'lmap' (did you mean 'lamp'?)",
                Recipes.error(REGISTRY, "lights:\n  - {type: lmap, position: [0, 1, 0]}\n"));
        assertEquals(new Lamp(new glint.math.Vector3d(0, 3, 6), glint.math.Vector3d.ONE, 3),
                Recipes.scene(REGISTRY, SCENE).lights().get(0));
    }

    /**
     * How far the segment from a to b passes outside the ball (the distance from the ball's centre
     * to the segment less its radius): negative when it goes through the ball.
     */
    private static double segmentMissBy(double[] a, double[] b) {
        double[] ab = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double[] ac = {BALL[0] - a[0], BALL[1] - a[1], BALL[2] - a[2]};
        double s = Math.max(0, Math.min(1, dot(ac, ab) / dot(ab, ab)));
        double[] nearest = {a[0] + s * ab[0] - BALL[0], a[1] + s * ab[1] - BALL[1], a[2] + s * ab[2] - BALL[2]};
        return Math.sqrt(dot(nearest, nearest)) - BALL_RADIUS;
    }

    private static double[] scale(double[] v, double k) {
        return new double[] {v[0] * k, v[1] * k, v[2] * k};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
}
