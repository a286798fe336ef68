package glint.shading;

/**
 * What Whitted's shading models read while they shade one vertex of a path: the compiled scene's
 * materials, lights and ambient light, and the shadow rays ({@link LightQuery}). All vectors are
 * world space, directions unit length.
 */
public interface ShadingContext extends LightQuery {

    Materials materials();

    Lights lights();

    /** The scene's ambient light, channel 0, 1 or 2. */
    double ambient(int channel);
}
