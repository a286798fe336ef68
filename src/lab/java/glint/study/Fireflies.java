package glint.study;

import glint.math.Vector3d;
import glint.render.PinholeCamera;
import glint.render.Tracer;
import glint.scene.Camera;
import glint.scene.Scene;
import java.util.Locale;

/**
 * Fireflies from a glossy bounce to a point light: a grey matte floor (y = 0), a white metal wall
 * (x = 0) of the given roughness, one small strong point light between them, black background;
 * the camera sees only the floor. A path of two hits (floor, then what the floor's sample meets)
 * carries the floor's direct light and the light the wall reflects onto it, found by the light
 * sample at the wall: its GGX lobe, as narrow as alpha, gives rare huge values as roughness falls.
 * Where the wall is nearly a mirror, that light is the light's mirror image's, in closed form
 * ({@link #mirrorRadiance}); below {@link glint.shading.Microfacet#MIRROR_ALPHA} the wall is a delta
 * mirror, which no light sample sees, and the floor has its direct light only.
 */
final class Fireflies {

    static final double ALBEDO = 0.5;
    static final double INTENSITY = 20;
    /** The light: 0.3 in front of the wall, 0.5 above the floor. */
    static final Vector3d LIGHT = new Vector3d(0.3, 0.5, 0);
    static final int WIDTH = 48, HEIGHT = 36;

    private Fireflies() {
    }

    static String yaml(double roughness) {
        return String.format(Locale.ROOT, """
                camera: {position: [0.8, 1.6, -1.2], look_at: [0.8, 0, 0.1], fov: 30}
                background: [0, 0, 0]
                lights:
                  - {type: point, position: [%s, %s, %s], intensity: %s}
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [%s, %s, %s]}}
                  - {type: plane, point: [0, 0, 0], normal: [1, 0, 0], material: {type: metal, color: [1, 1, 1], roughness: %s}}
                """, LIGHT.x(), LIGHT.y(), LIGHT.z(), INTENSITY, ALBEDO, ALBEDO, ALBEDO, roughness);
    }

    static Scene scene(double roughness) {
        return PassSamples.parse("fireflies.yaml", yaml(roughness));
    }

    /** Every sample of the scene at this roughness, paths of two hits. */
    static PassSamples render(double roughness, int samples, Tracer tracer) {
        return PassSamples.render(scene(roughness), WIDTH, HEIGHT, samples, 2, tracer);
    }

    /** The floor's radiance at (x, 0, z) from the light alone: albedo / pi x I cos / d^2. */
    static double directRadiance(double x, double z) {
        return lambert(x - LIGHT.x(), LIGHT.y(), z - LIGHT.z());
    }

    /**
     * The floor's radiance at (x, 0, z) with a perfect white mirror for a wall: its direct light plus
     * the light of the light's mirror image behind the wall, at (-lx, ly, lz), which it always sees
     * (the line to it crosses the wall above the floor).
     */
    static double mirrorRadiance(double x, double z) {
        return directRadiance(x, z) + lambert(x + LIGHT.x(), LIGHT.y(), z - LIGHT.z());
    }

    private static double lambert(double dx, double height, double dz) {
        double d2 = dx * dx + height * height + dz * dz;
        return ALBEDO / Math.PI * INTENSITY * (height / Math.sqrt(d2)) / d2;
    }

    /**
     * The mean over the image of a radiance of the floor point each pixel sees, each pixel averaged
     * over k x k points: what a render's mean converges to when the floor has that radiance.
     */
    static double imageMean(boolean mirror, int k) {
        Camera camera = scene(0.5).camera();
        double sum = 0;
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                for (int i = 0; i < k; i++) {
                    for (int j = 0; j < k; j++) {
                        Vector3d d = new PinholeCamera(camera).direction(x + (i + 0.5) / k, y + (j + 0.5) / k,
                                WIDTH, HEIGHT);
                        double t = -camera.position().y() / d.y();
                        double px = camera.position().x() + t * d.x(), pz = camera.position().z() + t * d.z();
                        sum += mirror ? mirrorRadiance(px, pz) : directRadiance(px, pz);
                    }
                }
            }
        }
        return sum / (WIDTH * HEIGHT * k * k);
    }
}
