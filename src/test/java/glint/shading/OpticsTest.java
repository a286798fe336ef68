package glint.shading;

import glint.geometry.Intersect;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Fresnel, refraction and total internal reflection against textbook values. */
class OpticsTest {

    @Test
    void exactFresnelAtNormalIncidenceIsTheSquaredReflectionCoefficient() {
        // ((n1 - n2) / (n1 + n2))^2 = (0.5 / 2.5)^2 = 0.04, from either side
        assertEquals(0.04, Optics.fresnelDielectric(1, 1 / 1.5), 1e-15);
        assertEquals(0.04, Optics.fresnelDielectric(1, 1.5), 1e-15);
    }

    @Test
    void exactFresnelAtGrazingIncidenceIsOne() {
        assertEquals(1, Optics.fresnelDielectric(0, 1 / 1.5), 1e-15);
    }

    @Test
    void exactFresnelAtBrewstersAngleHasNoPPolarisedPart() {
        // tan(theta_B) = 1.5: rp = 0, so F = rs^2 / 2 with rs = (cos i - 1.5 cos t) / (cos i + 1.5 cos t)
        double thetaB = Math.atan(1.5);
        double cosI = Math.cos(thetaB);
        double cosT = Math.cos(Math.PI / 2 - thetaB);
        double rs = (cosI - 1.5 * cosT) / (cosI + 1.5 * cosT);
        assertEquals(rs * rs / 2, Optics.fresnelDielectric(cosI, 1 / 1.5), 1e-12);
    }

    @Test
    void totalInternalReflectionBeginsAtTheCriticalAngle() {
        double critical = Math.toDegrees(Math.asin(1 / 1.5));
        assertEquals(41.81, critical, 0.005);
        double[] out = new double[3];
        double below = Math.toRadians(41.7), above = Math.toRadians(41.9);
        assertTrue(Optics.fresnelDielectric(Math.cos(below), 1.5) < 1);
        assertEquals(1, Optics.fresnelDielectric(Math.cos(above), 1.5));
        // inside glass, going up through a boundary with normal +y (facing the incident side: -y... )
        assertTrue(Optics.refract(Math.sin(below), Math.cos(below), 0, 0, -1, 0, Math.cos(below), 1.5, out));
        assertFalse(Optics.refract(Math.sin(above), Math.cos(above), 0, 0, -1, 0, Math.cos(above), 1.5, out));
    }

    @Test
    void refractionObeysSnellsLaw() {
        double thetaI = Math.toRadians(30);
        double[] out = new double[3];
        // travelling down (-y) into a surface whose normal +y faces the incident side
        assertTrue(Optics.refract(Math.sin(thetaI), -Math.cos(thetaI), 0, 0, 1, 0, Math.cos(thetaI), 1 / 1.5, out));
        assertEquals(Math.sin(thetaI) / 1.5, out[0], 1e-15);
        assertEquals(-Math.sqrt(1 - Math.pow(Math.sin(thetaI) / 1.5, 2)), out[1], 1e-15);
        assertEquals(0, out[2]);
    }

    @Test
    void rayThroughAGlassSlabLeavesParallelAndOffsetByTheTextbookAmount() {
        // slab between planes z = 0 and z = 2, ior 1.5; ray from (0,0,-1) at 40 degrees in the x-z plane
        double thickness = 2, ior = 1.5, theta = Math.toRadians(40);
        double dx = Math.sin(theta), dz = Math.cos(theta);
        double ox = -dx / dz, oz = -1;
        // entry face, normal facing the ray
        double t1 = Intersect.planeBefore(0, 0, -1, 0, ox, 0, oz, dx, 0, dz, Intersect.MISS);
        double px = ox + t1 * dx, pz = oz + t1 * dz;
        assertEquals(0, px, 1e-15);
        double[] inside = new double[3];
        assertTrue(Optics.refract(dx, 0, dz, 0, 0, -1, dz, 1 / ior, inside));
        double t2 = Intersect.planeBefore(0, 0, 1, thickness, px, 0, pz, inside[0], inside[1], inside[2],
                Intersect.MISS);
        double qx = px + t2 * inside[0], qz = pz + t2 * inside[2];
        assertEquals(thickness, qz, 1e-12);
        double[] outside = new double[3];
        assertTrue(Optics.refract(inside[0], inside[1], inside[2], 0, 0, -1, inside[2], ior, outside));
        assertEquals(dx, outside[0], 1e-14, "leaves parallel to how it came");
        assertEquals(dz, outside[2], 1e-14);
        // lateral displacement d = t sin(theta - theta') / cos(theta')
        double thetaT = Math.asin(Math.sin(theta) / ior);
        double expected = thickness * Math.sin(theta - thetaT) / Math.cos(thetaT);
        // distance between the exit point and the undeviated line x = z tan(theta), measured across it
        double undeviatedX = qz * Math.tan(theta);
        double displacement = (undeviatedX - qx) * Math.cos(theta);
        assertEquals(expected, displacement, 1e-12);
    }

    @Test
    void schlickMatchesF0AtNormalAndOneAtGrazing() {
        assertEquals(0.3, Optics.schlick(0.3, 1), 1e-15);
        assertEquals(1, Optics.schlick(0.3, 0), 1e-15);
        assertEquals(0.3 + 0.7 * Math.pow(0.5, 5), Optics.schlick(0.3, 0.5), 1e-15);
    }

    @Test
    void ggxIntegratesToOneOverProjectedHemisphere() {
        // integral of D(h) cos(theta_h) dw_h = 1 for any alpha (normalisation of a microfacet NDF)
        for (double alpha : new double[] {0.05, 0.3, 1.0}) {
            int n = 200_000;
            double sum = 0;
            for (int i = 0; i < n; i++) {
                double u = (i + 0.5) / n; // cos(theta) uniformly: dw = 2 pi d(cos)
                sum += Optics.ggx(u, alpha) * u * 2 * Math.PI / n;
            }
            assertEquals(1, sum, 2e-3, "alpha " + alpha);
        }
    }

    @Test
    void schlickForGlassAgreesAtTheEndsAndHandlesTotalInternalReflection() {
        assertEquals(0.04, Optics.schlickDielectric(1, 1 / 1.5), 1e-15);
        assertEquals(0.04, Optics.schlickDielectric(1, 1.5), 1e-15);
        assertEquals(1, Optics.schlickDielectric(0, 1 / 1.5), 1e-15);
        assertEquals(1, Optics.schlickDielectric(Math.cos(Math.toRadians(45)), 1.5), 0, "past 41.8 degrees inside");
        // exact 0.0892, Schlick 0.0700 at 60 degrees from outside: close, not equal
        double cos60 = 0.5;
        assertEquals(Optics.fresnelDielectric(cos60, 1 / 1.5), Optics.schlickDielectric(cos60, 1 / 1.5), 0.025);
    }
}
