package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.accel.FlatList;
import glint.image.FrameBuffer;
import glint.scene.Scene;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Glass walks the inside of a closed primitive nothing else reaches into in closed form; the plain
 * search (a flat list of every primitive, which knows no empty insides) follows the same rays. On
 * seeded random scenes with glass spheres alone, resting on the floor, cut by it, overlapping and
 * nested in others, both give the same image to float rounding and cast the same rays, with
 * pruning off and with the roulette (its numbers drawn in the same order).
 */
class InsideWalkTest {

    private static final long SEED = 20_261_202L;
    /**
     * The relative mean square error two renders of the same rays may differ by: a few of the
     * float image's values one rounding step apart give 1e-19 to 1e-16 here; a factor off by 1e-4 on
     * the light reflected inside the glass alone already gives more.
     */
    private static final double ROUNDING = 1e-13;

    @Test
    void theWalkRendersWhatThePlainSearchRenders() {
        Random random = new Random(SEED);
        int walked = 0;
        for (int i = 0; i < 12; i++) {
            Scene scene = Renders.scene(glassScene(random));
            Shading shading = i % 3 == 2 ? Shading.PHONG : Shading.COOK_TORRANCE;
            double minWeight = i % 2 == 0 ? 0 : 0.05;
            RenderSettings settings = new RenderSettings(shading, 6 + i % 4, minWeight, Renders.EPSILON);
            RenderScene withWalk = RenderScene.compile(scene, settings);
            RenderScene searched = RenderScene.compile(scene, settings, FlatList::new);
            FrameBuffer a = new FrameBuffer(40, 30), b = new FrameBuffer(40, 30);
            long raysWalking = Renders.renderCountingRays(withWalk, a, 4);
            long raysSearching = Renders.renderCountingRays(searched, b, 4);
            String what = "scene " + i + ", " + shading + ", min_weight " + minWeight;
            assertEquals(raysSearching, raysWalking, what + ": the same rays");
            double error = relativeMse(b.rgb(), a.rgb());
            assertTrue(error <= ROUNDING, what + ": relative mean square error " + error);
            walked += hasEmptyInside(withWalk) ? 1 : 0;
        }
        assertTrue(walked >= 6, "scenes with an empty glass inside to walk: " + walked);
    }

    /** Whether any primitive of the scene has an empty inside (so that its glass walks it). */
    private static boolean hasEmptyInside(RenderScene scene) {
        for (int p = 0; p < scene.primitives.count(); p++) {
            if (scene.aggregate.emptyInside(p)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Glass spheres, some tinted, on a matte floor beside matte and metal ones: some float free,
     * some rest on the floor, some cut it, some overlap or hold another.
     */
    private static String glassScene(Random random) {
        StringBuilder yaml = new StringBuilder("""
                camera: {position: [0.5, 2.5, -7], look_at: [0, 0.8, 0], fov: 55}
                background: [0.3, 0.4, 0.7]
                lights:
                  - {type: point, position: [-4, 8, -5], intensity: 90}
                  - {type: directional, direction: [1, -2, 1], intensity: 0.5}
                materials:
                  clear: {type: glass, ior: 1.5}
                  green: {type: glass, ior: 1.33, color: [0.7, 1, 0.8]}
                  dense: {type: glass, ior: 2.4}
                  red: {type: matte, color: [0.8, 0.2, 0.1]}
                  gold: {type: metal, color: [1, 0.8, 0.4], roughness: 0.2}
                objects:
                  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.5, 0.5, 0.5]}}
                """);
        String[] materials = {"clear", "green", "dense", "clear", "red", "gold"};
        for (int i = 0, n = 2 + random.nextInt(7); i < n; i++) {
            double radius = 0.3 + random.nextDouble();
            double x = 6 * random.nextDouble() - 3, z = 4 * random.nextDouble() - 1;
            double y = switch (random.nextInt(3)) {
                case 0 -> radius; // resting on the floor
                case 1 -> radius * random.nextDouble(); // cut by it
                default -> radius + 2 * random.nextDouble(); // floating
            };
            String material = materials[random.nextInt(materials.length)];
            yaml.append(sphere(x, y, z, radius, material));
            if (random.nextInt(4) == 0) { // a smaller sphere inside it
                yaml.append(sphere(x, y, z, radius * 0.4, materials[random.nextInt(3)]));
            }
        }
        return yaml.toString();
    }

    private static String sphere(double x, double y, double z, double radius, String material) {
        return String.format(Locale.ROOT, "  - {type: sphere, center: [%.3f, %.3f, %.3f], radius: %.3f, material: %s}%n",
                x, y, z, radius, material);
    }

    private static double relativeMse(float[] expected, float[] actual) {
        double error = 0, energy = 0;
        for (int i = 0; i < expected.length; i++) {
            double d = expected[i] - actual[i];
            error += d * d;
            energy += (double) expected[i] * expected[i];
        }
        return energy == 0 ? error : error / energy;
    }
}
