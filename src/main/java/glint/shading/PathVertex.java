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
    /** A BSDF's value while the lights are summed. */
    public final Rgb f = new Rgb();
    /**
     * The single rays the surface sends on ({@link ShadingModel#specular}): the factors of the
     * mirrored ray, and where it refracts, eta = n_incident / n_transmitted and the tint of the
     * refracted ray (0 for none).
     */
    public double reflectR, reflectG, reflectB, eta, transmitR, transmitG, transmitB;
    /**
     * Along a walk inside a closed primitive: the path weight of the ray that met this vertex, what
     * its reflected ray counts for, and whether the ray leaving through the surface refracts
     * ({@link #refracted}) rather than reflects.
     */
    public double weight, keepReflected;
    public boolean leavesThrough;

    public void setReflect(double r, double g, double b) {
        reflectR = r;
        reflectG = g;
        reflectB = b;
    }

    public void setTransmit(double r, double g, double b) {
        transmitR = r;
        transmitG = g;
        transmitB = b;
    }

    /** The largest factor of the mirrored ray. */
    public double reflectMax() {
        return Math.max(reflectR, Math.max(reflectG, reflectB));
    }
}
