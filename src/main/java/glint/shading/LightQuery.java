package glint.shading;

/** The renderer's shadow rays, as shading asks for them. */
public interface LightQuery {

    /**
     * Light i seen from surface s, into {@code out} (with {@code out.cosine} = |n.l|): the fraction of
     * it that reaches s, through the shadow pass of whatever its shadow ray meets; 0 where it is
     * blocked, and where it is behind the surface unless {@code through} (a surface with a lobe that
     * is not a delta and sends light through it, rough glass), whose shadow ray then leaves from the
     * far side.
     */
    double lightReaching(Surface s, int i, boolean through, LightSample out);
}
