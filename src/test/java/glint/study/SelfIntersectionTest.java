package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.config.Config;
import glint.render.Tracer;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Fixed epsilon against Glint's offset epsilon x max(1, |p|), for a contact scene moved ever further
 * from the origin. A hit point at magnitude |p| is off by a few units in the last place, ~|p| u
 * (u = 6e-8 in float, 1.1e-16 in double): a fixed offset eps stops covering it once |p| u ~ eps,
 * while the scaled offset covers it at every |p| as long as epsilon >> u. Moving a ray's origin by h
 * changes no shadow whose ray passes deeper than h inside (or clearer than h outside) an occluder.
 */
class SelfIntersectionTest {

    private static final ShadowScene SCENE = ShadowScene.contact(80, 60);
    private static ShadowTruth truth;
    private static Tracer tracer;

    @BeforeAll
    static void setUp() {
        truth = ShadowTruth.of(SCENE);
        tracer = new Tracer(2);
    }

    @AfterAll
    static void tearDown() {
        tracer.close();
    }

    private static OffsetErrors run(OffsetMethod method, double s) {
        return OffsetStudy.moved(SCENE, truth, s, method, tracer);
    }

    @Test
    void theTruthHasLitAndShadowedPixels() {
        assertTrue(truth.count(ShadowTruth.LIT) > 1000);
        assertTrue(truth.count(ShadowTruth.SHADOW) > 200);
    }

    @Test
    void glintsScaledOffsetShowsNoAcneUpTo1e7() {
        OffsetMethod glint = new OffsetMethod.Glint(Config.defaults().epsilon());
        for (double s : new double[] {1, 1e3, 1e5, 1e7}) {
            OffsetErrors e = run(glint, s);
            assertEquals(0, e.acne(), "acne at s = " + s);
            assertEquals(0, e.unexplained(), "every missed shadow lies within the offset at s = " + s);
        }
    }

    @Test
    void glintKeepsEveryContactShadowWhileTheOffsetIsBelowTheirDepth() {
        // at s = 1e5 the offset is 1e-9 x 1.7e5 = 1.7e-4, below the truth margin of 1e-3
        OffsetErrors e = run(new OffsetMethod.Glint(Config.defaults().epsilon()), 1e5);
        assertEquals(0, e.missedShadow());
        assertEquals(0, e.overshoot());
    }

    @Test
    void fixedEpsilonInFloatShowsAcneFarFromTheOrigin() {
        OffsetMethod fixed = new OffsetMethod.Fixed(Precision.FLOAT, 1e-4);
        // |p| ~ 17 at s = 10: rounding ~1e-6, far below 1e-4
        assertEquals(0, run(fixed, 10).acne());
        // |p| ~ 1.7e4 at s = 1e4: rounding ~1e-3, ten times the offset
        assertTrue(run(fixed, 1e4).acne() > 0);
    }

    @Test
    void fixedEpsilonInDoubleHoldsTo1e7AndFailsBy1e13() {
        OffsetMethod fixed = new OffsetMethod.Fixed(Precision.DOUBLE, 1e-4);
        // rounding at |p| = 1.7e7: ~4e-9, far below 1e-4
        assertEquals(0, run(fixed, 1e7).acne());
        // rounding at |p| = 1.7e13: ~4e-3 > 1e-4
        assertTrue(run(fixed, 1e13).acne() > 0);
    }

    @Test
    void aHugeGroundSphereNearTheOriginStaysCleanWhileItsRoundingIsBelowTheOffset() {
        // the re-projected point c + r n is off by ~r u: 1e5 x 1.1e-16 = 1.1e-11 < 1e-9
        OffsetMethod glint = new OffsetMethod.Glint(Config.defaults().epsilon());
        for (double r : new double[] {1, 1e3, 1e5}) {
            assertEquals(0, OffsetStudy.moved(ShadowScene.groundSphere(r, 40, 30), 0, glint, tracer).acne(), "r = " + r);
        }
    }
}
