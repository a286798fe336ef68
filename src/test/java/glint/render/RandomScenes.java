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

    /** A unit direction at {@code angle} radians from unit vector {@code axis}, turned towards a random side. */
    static double[] atAngle(double[] axis, double angle, SplittableRandom random) {
        double[] v = unitVector(random);
        double along = axis[0] * v[0] + axis[1] * v[1] + axis[2] * v[2];
        double[] side = {v[0] - along * axis[0], v[1] - along * axis[1], v[2] - along * axis[2]};
        double length = Math.sqrt(side[0] * side[0] + side[1] * side[1] + side[2] * side[2]);
        double c = Math.cos(angle), s = Math.sin(angle) / length;
        return new double[] {c * axis[0] + s * side[0], c * axis[1] + s * side[1], c * axis[2] + s * side[2]};
    }

    /**
     * A random sphere as a point light sees it: the unit direction towards its centre, the
     * distance to the centre (1 to 50) and a radius of 0.1 % to 90 % of it.
     */
    record SeenSphere(double[] towards, double distance, double radius) {

        static SeenSphere random(SplittableRandom random) {
            double[] towards = unitVector(random);
            double distance = random.nextDouble(1, 50);
            return new SeenSphere(towards, distance, distance * random.nextDouble(1e-3, 0.9));
        }

        /** The sphere's centre and radius (cx, cy, cz, r) for a light at (x, y, z). */
        double[] from(double x, double y, double z) {
            return new double[] {x + towards[0] * distance, y + towards[1] * distance, z + towards[2] * distance,
                    radius};
        }

        /** The half-angle of the cone of directions the sphere fills. */
        double halfAngle() {
            return Math.asin(radius / distance);
        }

        /**
         * An angle from the cone's axis that its widened cone holds: for even {@code i} within the
         * half-angle, for odd ones within the margin ({@link ConeCells#ANGLE_MARGIN}) beyond it.
         */
        double angleWithinMargin(int i, SplittableRandom random) {
            return i % 2 == 0 ? halfAngle() * random.nextDouble()
                    : halfAngle() + ConeCells.ANGLE_MARGIN * random.nextDouble(0, 0.999);
        }
    }

    /** A scene of 1 to 6 spheres (few enough to be searched one by one), a floor, 1 to 3 lights and a random camera. */
    static String upToSixSpheres(Random random) {
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
        for (int i = 0, n = 1 + random.nextInt(6); i < n; i++) {
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
