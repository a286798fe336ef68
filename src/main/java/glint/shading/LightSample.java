package glint.shading;

/** Scratch value: one light seen from a surface point (world space). */
public final class LightSample {

    /** Unit direction towards the light. */
    public double dirX, dirY, dirZ;
    /** n.l: the cosine between the surface's normal and the direction towards the light. */
    public double cosine;
    /** Distance to the light; infinite for a directional one. */
    public double distance;
    /** Irradiance on a surface facing the light. */
    public double irradianceR, irradianceG, irradianceB;
}
