package glint.shading;

/**
 * The seed's model (docs/conventions.md, "phong"): ka ambient x colour + the sum over lights of (kd
 * colour E n.l + ks E (r.v)^shininess), + ks I_reflected + kt colour I_transmitted, with ka = kd,
 * whatever the material's type, and the light a surface sends of its own (a light's body). A shadow ray passes kt of the light through each object whose material
 * transmits light.
 */
public final class Phong implements ShadingModel {

    /** Ambient, and per light the diffuse term and the highlight, through what the shadow ray passes. */
    @Override
    public void direct(ShadingContext c, Surface s, double dx, double dy, double dz, LightSample light, Rgb f,
                       Rgb sum) {
        Materials m = c.materials();
        int material = s.material;
        double diffuseR = c.ambient(0), diffuseG = c.ambient(1), diffuseB = c.ambient(2);
        double specR = 0, specG = 0, specB = 0;
        double kd = m.kd(material), ks = m.ks(material);
        Lights lights = c.lights();
        // a surface without diffuse or highlight (a light's body) sends no light of the lights: no shadow rays
        for (int i = 0, n = kd == 0 && ks == 0 ? 0 : lights.count(); i < n; i++) {
            double pass = c.lightReaching(s, i, false, light);
            if (!(pass > 0)) {
                continue;
            }
            double cosLight = light.cosine;
            diffuseR += pass * light.irradianceR * cosLight;
            diffuseG += pass * light.irradianceG * cosLight;
            diffuseB += pass * light.irradianceB * cosLight;
            double cosReflectView = cosReflectView(s, light, dx, dy, dz);
            if (cosReflectView > 0) {
                double highlight = pass * Math.pow(cosReflectView, m.shininess(material));
                specR += highlight * light.irradianceR;
                specG += highlight * light.irradianceG;
                specB += highlight * light.irradianceB;
            }
        }
        sum.set(kd * m.color(material, 0) * diffuseR + ks * specR, kd * m.color(material, 1) * diffuseG + ks * specG,
                kd * m.color(material, 2) * diffuseB + ks * specB);
        if (m.emits(material)) { // a light's body is seen in every model
            m.bsdf(material).emitted(m, s, f);
            sum.set(sum.r + f.r, sum.g + f.g, sum.b + f.b);
        }
    }

    /** ks of the light reflected, kt x colour of the light refracted, whatever the angle. */
    @Override
    public void specular(ShadingContext c, Surface s, SingleRays out) {
        Materials m = c.materials();
        int material = s.material;
        double kt = m.kt(material), ks = m.ks(material);
        out.eta = Optics.eta(m.ior(material), s.front);
        out.setReflect(ks, ks, ks);
        out.setTransmit(kt * m.color(material, 0), kt * m.color(material, 1), kt * m.color(material, 2));
    }

    /**
     * The highlight's cosine: r.v with r the light direction mirrored about n and v = -d (raise it
     * to the shininess where positive).
     */
    private static double cosReflectView(Surface s, LightSample l, double dx, double dy, double dz) {
        double k = 2 * l.cosine;
        return -((k * s.nx - l.dirX) * dx + (k * s.ny - l.dirY) * dy + (k * s.nz - l.dirZ) * dz);
    }
}
