package glint.shading;

/** The renderer's shadow rays, as shading asks for them. */
public interface LightQuery {

    /**
     * Light i seen from surface s, into {@code out} (with {@code out.cosine} = n.l): the fraction of
     * it that reaches s, through the shadow pass of whatever its shadow ray meets; 0 where the light
     * is behind the surface or blocked.
     */
    double lightReaching(Surface s, int i, LightSample out);
}
