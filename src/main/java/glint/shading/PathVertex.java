package glint.shading;

import glint.geometry.Hit;

/**
 * The scratch values of one vertex of a path: the hit, the surface there, a light sample, the
 * direction a refraction writes, the sum being built, the radiance the vertex sends back, and the
 * factors of a refracting boundary. A render thread keeps one per level of recursion, so a ray
 * traced from a vertex never overwrites it.
 */
public final class PathVertex {

    public final Hit hit = new Hit();
    public final Surface surface = new Surface();
    public final LightSample light = new LightSample();
    public final double[] refracted = new double[3];
    public final Rgb sum = new Rgb();
    public final Rgb radiance = new Rgb();
    /**
     * Where the surface's material refracts ({@link ShadingModel#boundary}): eta = n_incident /
     * n_transmitted, the grey factor of the reflected ray and the tint of the refracted one.
     */
    public double eta, reflect, transmitR, transmitG, transmitB;
    /**
     * Along a walk inside a closed primitive: the path weight of the ray that met this vertex, what
     * its reflected ray counts for, and whether the ray leaving through the surface refracts
     * ({@link #refracted}) rather than reflects.
     */
    public double weight, keepReflected;
    public boolean leavesThrough;
}
