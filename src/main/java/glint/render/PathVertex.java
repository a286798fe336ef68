package glint.render;

import glint.geometry.Hit;
import glint.shading.LightSample;
import glint.shading.Rgb;
import glint.shading.Surface;

/**
 * The scratch values of one vertex of a path: the hit, the surface there, a light sample, the
 * direction a refraction writes, the sum being built, and the radiance the vertex sends back. A
 * worker keeps one per level of recursion, so a ray traced from a vertex never overwrites it.
 */
final class PathVertex {

    final Hit hit = new Hit();
    final Surface surface = new Surface();
    final LightSample light = new LightSample();
    final double[] refracted = new double[3];
    final Rgb sum = new Rgb();
    final Rgb radiance = new Rgb();
}
