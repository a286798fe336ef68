package glint.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The aimed rays' densities: that they are densities, and that the rays aimed follow them. */
class LightTargetsTest {

    /** Two targets, one far and small, one near and large, and a light at the origin outside both. */
    private static final double[] BALLS = {0, 0, 5, 1, 3, 1, 0, 1.5};
    private static final double OWN = 1 / (4 * Math.PI); // a point light's own density of each direction

    /** Over the sphere of directions the mixture's density integrates to 1 (uniform directions, 10^6 of them). */
    @Test
    void theDensityOfADirectionIntegratesToOne() {
        LightTargets targets = LightTargets.of(BALLS);
        Random random = new Random(3);
        double[] w = new double[3];
        int n = 1_000_000;
        double sum = 0;
        for (int k = 0; k < n; k++) {
            Directions.uniform(random.nextDouble(), random.nextDouble(), w);
            sum += targets.pdf(0, 0, 0, w[0], w[1], w[2], OWN) / OWN;
        }
        assertEquals(1, sum / n, 0.01);
    }

    /**
     * Rays drawn as the light subpath draws them (own or aimed, by the chance), each weighed by 1 over
     * its density, estimate the solid angle of a cone: the near target's, 2 pi (1 - cos theta).
     */
    @Test
    void raysDrawnByTheMixtureOverItsDensityMeasureATargetsSolidAngle() {
        LightTargets targets = LightTargets.of(BALLS);
        Random random = new Random(4);
        LightRay ray = new LightRay();
        int n = 400_000;
        double sum = 0;
        for (int k = 0; k < n; k++) {
            Directions.uniform(random.nextDouble(), random.nextDouble(), ray.scratch);
            ray.setDirection(ray.scratch[0], ray.scratch[1], ray.scratch[2]);
            int j = targets.choose(random.nextDouble());
            if (j >= 0) {
                assertTrue(targets.aim(j, 0, 0, 0, random.nextDouble(), random.nextDouble(), ray));
            }
            double pdf = targets.pdf(0, 0, 0, ray.dirX, ray.dirY, ray.dirZ, OWN);
            double dx = 3 - 0, dy = 1, dz = 0, d = Math.sqrt(dx * dx + dy * dy + dz * dz);
            boolean inNear = Cone.contains(dx / d, dy / d, dz / d, 1.5 * 1.5 / (d * d), ray.dirX, ray.dirY, ray.dirZ);
            sum += inNear ? 1 / pdf : 0;
        }
        double d2 = 10;
        double expected = 2 * Math.PI * Cone.oneMinusCos(1.5 * 1.5 / d2);
        assertEquals(expected, sum / n, 0.01 * expected);
    }

    /** The chance to aim is {@link LightTargets#AIMED}, spread evenly over the targets. */
    @Test
    void aRayAimsWithTheChanceAimedAtEachTargetAlike() {
        LightTargets targets = LightTargets.of(BALLS);
        assertEquals(-1, targets.choose(LightTargets.AIMED));
        assertEquals(0, targets.choose(0));
        assertEquals(0, targets.choose(LightTargets.AIMED / 2 - 1e-9));
        assertEquals(1, targets.choose(LightTargets.AIMED / 2));
        assertEquals(1, targets.choose(Math.nextDown(LightTargets.AIMED)));
        assertEquals(-1, LightTargets.none().choose(0));
    }

    /** From inside a target's ball there is no cone: that target leaves the ray to the light's own density. */
    @Test
    void fromInsideATargetTheLightsOwnDensityStandsForIt() {
        LightTargets targets = LightTargets.of(new double[] {0, 0, 0, 2});
        LightRay ray = new LightRay();
        assertTrue(!targets.aim(0, 0.5, 0, 0, 0.3, 0.7, ray));
        assertEquals(OWN, targets.pdf(0.5, 0, 0, 0, 0, 1, OWN), 1e-15);
    }

    /**
     * A light at infinity's disc: the mixture's density of the disc's points integrates to 1 over the disc
     * (uniform points), and an aimed point lies in the plane of the disc, in the target's shadow.
     */
    @Test
    void aFarLightsDiscPointsHaveADensityAndAimedOnesFallInTheShadow() {
        LightTargets targets = LightTargets.of(BALLS);
        double radius = 10, area = Math.PI * radius * radius;
        double dx = 0.6, dy = -0.8, dz = 0; // the rays' direction, from the light
        LightRay ray = new LightRay();
        Random random = new Random(6);
        int n = 1_000_000;
        double sum = 0;
        for (int k = 0; k < n; k++) {
            Directions.onDisc(-dx * radius, -dy * radius, -dz * radius, -dx, -dy, -dz, radius, random.nextDouble(),
                    random.nextDouble(), ray.frame, ray.scratch);
            sum += targets.pdfAcross(ray.scratch[0], ray.scratch[1], ray.scratch[2], dx, dy, dz, 1 / area) * area;
        }
        assertEquals(1, sum / n, 0.01);
        for (int k = 0; k < 1000; k++) {
            ray.setDirection(dx, dy, dz);
            targets.aimAcross(1, 0, 0, 0, radius, random.nextDouble(), random.nextDouble(), ray);
            double along = ray.originX * dx + ray.originY * dy + ray.originZ * dz;
            assertEquals(-radius, along, 1e-9, "on the disc's plane");
            double vx = 3 - ray.originX, vy = 1 - ray.originY, vz = -ray.originZ;
            double t = vx * dx + vy * dy + vz * dz;
            assertTrue(vx * vx + vy * vy + vz * vz - t * t <= 1.5 * 1.5 + 1e-9, "in the target's shadow");
        }
    }

    /** More targets than {@link LightTargets#MOST_TARGETS}: one ball around them all. */
    @Test
    void manyTargetsAreAimedAtAsOneBallAroundThemAll() {
        int n = LightTargets.MOST_TARGETS + 1;
        double[] balls = new double[4 * n];
        for (int i = 0; i < n; i++) {
            balls[4 * i] = i;
            balls[4 * i + 3] = 0.5;
        }
        LightTargets targets = LightTargets.of(balls);
        assertEquals(1, targets.count());
        // the ball around them: centre (8, 0, 0), radius 8.5; seen from (8, 0, -17) its cone is sin^2 = 8.5^2 / 17^2
        double inside = Math.sin(Math.asin(0.5) * 0.99), outside = Math.sin(Math.asin(0.5) * 1.01);
        double cosIn = Math.sqrt(1 - inside * inside), cosOut = Math.sqrt(1 - outside * outside);
        assertTrue(targets.pdf(8, 0, -17, inside, 0, cosIn, 0) > 0);
        assertEquals(0, targets.pdf(8, 0, -17, outside, 0, cosOut, 0));
    }
}
