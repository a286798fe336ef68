package glint.study;

import glint.math.Vector3d;
import glint.render.PinholeCamera;
import glint.render.Tracer;
import glint.scene.Camera;
import glint.scene.Scene;
import glint.shading.Optics;
import java.util.Locale;

/**
 * A clear glass ball (ior 1.5, radius 1, at the origin) against a bright uniform sky, seen from far
 * away (40 radii, nearly parallel rays), no lights: every path through the ball chooses at each
 * boundary between the Fresnel reflection and the refraction with probability F, each choice of
 * weight 1, so a sample is either the sky or, where the path meets something dark or runs out of
 * hits, 0. With {@code floor} a black floor just under the ball takes the light of every path that
 * reaches it; without, the scene is a furnace: energy is conserved and the ball would vanish, but a
 * path that is still inside after its last hit brings nothing, with probability
 * {@link #truncated} in closed form.
 */
final class GlassSky {

    static final double SKY = 10;
    static final double IOR = 1.5;
    static final int WIDTH = 48, HEIGHT = 48;
    static final Vector3d EYE = new Vector3d(0, 0, -40);

    private GlassSky() {
    }

    static String yaml(boolean floor) {
        return String.format(Locale.ROOT, """
                camera: {position: [%s, %s, %s], look_at: [0, 0, 0], fov: 3.5}
                background: [%s, %s, %s]
                objects:
                  - {type: sphere, center: [0, 0, 0], radius: 1, material: {type: glass, ior: %s}}
                """, EYE.x(), EYE.y(), EYE.z(), SKY, SKY, SKY, IOR)
                + (floor ? "  - {type: plane, point: [0, -1.001, 0], normal: [0, 1, 0], material: {type: matte, color: [0, 0, 0]}}\n"
                : "");
    }

    static Scene scene(boolean floor) {
        return PassSamples.parse("glass-sky.yaml", yaml(floor));
    }

    static PassSamples render(boolean floor, int samples, int hits, Tracer tracer) {
        return PassSamples.render(scene(floor), WIDTH, HEIGHT, samples, hits, tracer);
    }

    /**
     * The chance that a path entering the ball at impact parameter b (0 at the centre, 1 at the rim)
     * is still inside at its last of {@code hits} hits: refracted in (1 - F), then reflected inside at
     * each of the hits 2 .. hits - 1 (F each: a chord of a sphere meets the surface at the angle it
     * entered at, so every inner hit has the same F and none is past the critical angle).
     */
    static double truncated(double b, int hits) {
        if (b >= 1 || hits < 2) {
            return b >= 1 ? 0 : 1;
        }
        double f = Optics.fresnelDielectric(Math.sqrt(1 - b * b), 1 / IOR);
        return (1 - f) * Math.pow(f, hits - 2);
    }

    /** The impact parameter of the camera ray through image point (px, py), in radii. */
    static double impact(Camera camera, double px, double py) {
        Vector3d d = new PinholeCamera(camera).direction(px, py, WIDTH, HEIGHT);
        Vector3d toCentre = camera.position().scale(-1);
        double along = toCentre.dot(d);
        return Math.sqrt(Math.max(0, toCentre.dot(toCentre) - along * along));
    }

    /** Per pixel: the furnace's expected value over SKY, averaged over k x k points of the pixel. */
    static double[] furnaceExpected(int hits, int k) {
        Camera camera = scene(false).camera();
        double[] expected = new double[WIDTH * HEIGHT];
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                double sum = 0;
                for (int i = 0; i < k; i++) {
                    for (int j = 0; j < k; j++) {
                        sum += 1 - truncated(impact(camera, x + (i + 0.5) / k, y + (j + 0.5) / k), hits);
                    }
                }
                expected[y * WIDTH + x] = sum / (k * k);
            }
        }
        return expected;
    }

    /** Per pixel: the impact parameter of its centre. */
    static double[] centreImpacts() {
        Camera camera = scene(false).camera();
        double[] b = new double[WIDTH * HEIGHT];
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                b[y * WIDTH + x] = impact(camera, x + 0.5, y + 0.5);
            }
        }
        return b;
    }
}
