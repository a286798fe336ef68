package glint.shading;

/**
 * What shading reads and calls while it shades one vertex of a path: the compiled scene's
 * materials, lights and ambient light, and the renderer's rays (the shadow ray towards a light,
 * the reflected and refracted rays a surface sends on, and the pruning that decides whether one is
 * traced). All vectors are world space, directions unit length.
 */
public interface ShadingContext {

    Materials materials();

    Lights lights();

    /** The scene's ambient light, channel 0, 1 or 2. */
    double ambient(int channel);

    /** Whether a glass boundary reflects by the exact Fresnel equations (else by Schlick's). */
    boolean exactFresnel();

    /**
     * Light i seen from surface s, into {@code out} (with {@code out.cosine} = n.l): the fraction of
     * it that reaches s, through the shadow pass of whatever its shadow ray meets; 0 where the light
     * is behind the surface or blocked.
     */
    double lightReaching(Surface s, int i, LightSample out);

    /**
     * What a child ray of path weight {@code childWeight} counts for: 1 when it is traced as it is,
     * 0 when it is pruned, 1 / q when roulette kept it with probability q.
     */
    double keep(double childWeight);

    /**
     * Adds to {@code sum} the light mirrored at s (the mirror direction of d), weighted by the
     * factor fR, fG, fB per channel: the ray, of path weight weight x the largest factor, is traced
     * if {@link #keep} keeps it. {@code hitsLeft} counts this surface.
     */
    void addReflected(Surface s, double dx, double dy, double dz, int hitsLeft, double weight, double fR, double fG,
                      double fB, Rgb sum);

    /**
     * Adds to {@code v.sum} what v's refracting boundary (its factors from
     * {@link ShadingModel#boundary}) reflects and refracts.
     */
    void scatter(PathVertex v, double dx, double dy, double dz, int hitsLeft, double weight);
}
