package glint.shading;

/**
 * Glass to Whitted's models: the mirrored ray weighted by the Fresnel reflectance R at the cosine met,
 * the refracted one by (1 - R) x the colour, whatever the roughness (rough glass is followed along the
 * smooth one's two rays; the light loop lights its lobes, {@link Dielectric}); phong's shadow rays
 * pass through it.
 */
public final class GlassResponse implements WhittedResponse {

    @Override
    public void specular(Materials m, Surface s, SingleRays out) {
        int material = s.material;
        out.eta = Optics.eta(Dielectric.ior(m, material), s.front);
        double reflectance = Dielectric.reflectance(m, s.cosIncident, out.eta);
        out.setReflect(reflectance, reflectance, reflectance);
        out.setTransmit((1 - reflectance) * m.color(material, 0), (1 - reflectance) * m.color(material, 1),
                (1 - reflectance) * m.color(material, 2));
    }

    @Override
    public boolean transmits() {
        return true;
    }
}
