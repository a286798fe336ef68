package glint.shading;

/**
 * A metal to Whitted's models: the mirrored ray, weighted by Schlick's Fresnel per channel (F0 = the
 * colour) at the cosine met, whatever the roughness (a rough metal's lobe is followed along its mirror
 * direction; the light loop lights the lobe itself, {@link Conductor}).
 */
public final class MetalResponse implements WhittedResponse {

    @Override
    public void specular(Materials m, Surface s, SingleRays out) {
        int material = s.material;
        double cos = s.cosIncident;
        out.setReflect(Optics.schlick(m.color(material, 0), cos), Optics.schlick(m.color(material, 1), cos),
                Optics.schlick(m.color(material, 2), cos));
        out.setTransmit(0, 0, 0);
    }

    /** A metal's colour is its reflectance: phong's reflection and highlight take it. */
    @Override
    public boolean tintsReflection() {
        return true;
    }
}
