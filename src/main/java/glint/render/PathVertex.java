package glint.render;

import glint.geometry.Hit;
import glint.shading.LightSample;
import glint.shading.Rgb;
import glint.shading.Surface;

/**
 * The scratch values of one vertex of a path: the hit, the surface there, a light sample, the
 * direction a refraction writes, the sum being built, the radiance the vertex sends back, and the
 * factors of a refracting boundary. A
 * worker keeps one per level of recursion, so a ray traced from a vertex never overwrites it.
 */
final class PathVertex {

    final Hit hit = new Hit();
    final Surface surface = new Surface();
    final LightSample light = new LightSample();
    final double[] refracted = new double[3];
    final Rgb sum = new Rgb();
    final Rgb radiance = new Rgb();
    /**
     * Where the surface's material refracts ({@link ShadingModel#boundary}): eta = n_incident /
     * n_transmitted, the grey factor of the reflected ray and the tint of the refracted one.
     */
    double eta, reflect, transmitR, transmitG, transmitB;
    /**
     * Along a walk inside a closed primitive ({@link InsideWalk}): the path weight of the ray that
     * met this vertex, what its reflected ray counts for ({@link Integrator#keep}), and whether the
     * ray leaving through the surface refracts ({@link #refracted}) rather than reflects.
     */
    double weight, keepReflected;
    boolean leavesThrough;
}
