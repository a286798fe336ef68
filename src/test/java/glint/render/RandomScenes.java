package glint.render;

import java.util.Locale;
import java.util.Random;
import java.util.SplittableRandom;

/** Test helper: random scenes as scene-file text, from a seeded generator. */
final class RandomScenes {

    private RandomScenes() {
    }

    /** A random unit vector, uniform over directions (rejection from the unit ball's shell). */
    static double[] unitVector(SplittableRandom random) {
        while (true) {
            double x = random.nextDouble(-1, 1), y = random.nextDouble(-1, 1), z = random.nextDouble(-1, 1);
            double length = Math.sqrt(x * x + y * y + z * z);
            if (length > 0.1 && length <= 1) {
                return new double[] {x / length, y / length, z / length};
            }
        }
    }

    /** A scene of 1 to 6 spheres (few enough to be searched one by one), a floor, 1 to 3 lights and a random camera. */
    static String upToSixSpheres(Random random) {
        return withSpheres(random, 6);
    }

    /** A scene of 1 to {@code most} spheres, a floor, 1 to 3 lights and a random camera. */
    static String withSpheres(Random random, int most) {
        StringBuilder yaml = new StringBuilder();
        yaml.append(String.format(Locale.ROOT, "camera: {position: [%s, %s, %s], look_at: [%s, %s, %s], fov: %d}%n",
                coordinate(random, 6), 0.3 + 4 * random.nextDouble(), -4 - 4 * random.nextDouble(),
                coordinate(random, 1), random.nextDouble(), coordinate(random, 1), 30 + random.nextInt(60)));
        yaml.append("lights:\n");
        for (int i = 0, n = 1 + random.nextInt(3); i < n; i++) {
            if (random.nextInt(3) == 0) {
                yaml.append(String.format(Locale.ROOT,
                        "  - {type: directional, direction: [%s, -1, %s], color: [1, 1, 1], intensity: 1}%n",
                        coordinate(random, 1), coordinate(random, 1)));
            } else {
                yaml.append(String.format(Locale.ROOT,
                        "  - {type: point, position: [%s, %s, %s], color: [1, 1, 1], intensity: 60}%n",
                        coordinate(random, 5), 1 + 6 * random.nextDouble(), coordinate(random, 5)));
            }
        }
        yaml.append("objects:\n");
        String[] materials = {"{type: matte, color: [0.7, 0.3, 0.2]}", "{type: matte, color: [0.2, 0.6, 0.8]}",
                "{type: metal, color: [0.9, 0.8, 0.5], roughness: 0.1}", "{type: glass, ior: 1.5}"};
        for (int i = 0, n = 1 + random.nextInt(most); i < n; i++) {
            double radius = 0.2 + random.nextDouble();
            yaml.append(String.format(Locale.ROOT, "  - {type: sphere, center: [%s, %s, %s], radius: %s, material: %s}%n",
                    coordinate(random, 3), radius * random.nextDouble() * 2, coordinate(random, 3), radius,
                    materials[random.nextInt(4) < 3 ? random.nextInt(2) : 2 + random.nextInt(2)]));
        }
        yaml.append("  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, color: [0.5, 0.5, 0.5]}}\n");
        return yaml.toString();
    }

    private static double coordinate(Random random, double extent) {
        return extent * (2 * random.nextDouble() - 1);
    }
}
