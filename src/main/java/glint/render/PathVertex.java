package glint.render;

import glint.geometry.Hit;
import glint.shading.LightSample;
import glint.shading.Rgb;
import glint.shading.SingleRays;
import glint.shading.Surface;

/**
 * The scratch values of one level of {@link WhittedIntegrator}'s recursion: the hit, the surface
 * there, the sum the shading model builds (with its light sample and BSDF value), the factors of the
 * single rays, the direction of the refracted one and the radiance the level sends back. The
 * integrator keeps one per level, so a ray traced from a level never overwrites it; it alone
 * writes and reads them, passing each to the call that fills or reads it. The glass walk's bounces
 * are vertices too ({@link InsideWalk}).
 */
class PathVertex {

    final Hit hit = new Hit();
    final Surface surface = new Surface();
    final LightSample light = new LightSample();
    /** A BSDF's value while the lights are summed. */
    final Rgb f = new Rgb();
    final Rgb sum = new Rgb();
    final SingleRays rays = new SingleRays();
    /**
     * The direction of the refracted ray (in the glass walk, of the ray leaving the bounce: refracted,
     * or past the critical angle reflected).
     */
    final double[] refracted = new double[3];
    final Rgb radiance = new Rgb();
}
