package glint.shading;

/**
 * The seed's model (docs/conventions.md, "phong"): ka ambient x colour + the sum over lights of (kd
 * colour (E / pi) n.l + ks s (E / pi) (r.v)^shininess), + ks s I_reflected + kt colour I_transmitted, with
 * ka = kd, whatever the material's type, and the light a surface sends of its own (a light's body). E / pi
 * is the light term of Lambert's model, so a scene's physical lights give phong the brightness they give
 * cook-torrance; s is the colour of a material whose reflection takes it (a metal,
 * {@link WhittedResponse#tintsReflection}), white otherwise. A shadow ray passes kt of the light through
 * each object whose material transmits light.
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
        double lightR = 0, lightG = 0, lightB = 0;
        Lights lights = c.lights();
        // a surface without diffuse or highlight (a light's body) sends no light of the lights: no shadow rays
        for (int i = 0, n = kd == 0 && ks == 0 ? 0 : lights.count(); i < n; i++) {
            double pass = c.lightReaching(s, i, false, light);
            if (!(pass > 0)) {
                continue;
            }
            double cosLight = light.cosine;
            lightR += pass * light.irradianceR * cosLight;
            lightG += pass * light.irradianceG * cosLight;
            lightB += pass * light.irradianceB * cosLight;
            double cosReflectView = cosReflectView(s, light, dx, dy, dz);
            if (cosReflectView > 0) {
                double highlight = pass * Math.pow(cosReflectView, m.shininess(material));
                specR += highlight * light.irradianceR;
                specG += highlight * light.irradianceG;
                specB += highlight * light.irradianceB;
            }
        }
        diffuseR += lightR * INV_PI;
        diffuseG += lightG * INV_PI;
        diffuseB += lightB * INV_PI;
        double sR = ks * INV_PI, sG = sR, sB = sR;
        if (m.response(material).tintsReflection()) {
            sR *= m.color(material, 0);
            sG *= m.color(material, 1);
            sB *= m.color(material, 2);
        }
        sum.set(kd * m.color(material, 0) * diffuseR + sR * specR, kd * m.color(material, 1) * diffuseG + sG * specG,
                kd * m.color(material, 2) * diffuseB + sB * specB);
        if (m.emits(material)) { // a light's body is seen in every model
            m.bsdf(material).emitted(m, s, f);
            sum.set(sum.r + f.r, sum.g + f.g, sum.b + f.b);
        }
    }

    private static final double INV_PI = 1 / Math.PI;

    /**
     * ks of the light reflected (ks x colour for a material whose reflection takes its colour, a metal), kt x
     * colour of the light refracted, whatever the angle.
     */
    @Override
    public void specular(ShadingContext c, Surface s, SingleRays out) {
        Materials m = c.materials();
        int material = s.material;
        double kt = m.kt(material), ks = m.ks(material);
        out.eta = Optics.eta(m.ior(material), s.front);
        if (m.response(material).tintsReflection()) {
            out.setReflect(ks * m.color(material, 0), ks * m.color(material, 1), ks * m.color(material, 2));
        } else {
            out.setReflect(ks, ks, ks);
        }
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
