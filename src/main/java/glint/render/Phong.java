package glint.render;

import glint.shading.Bsdf;
import glint.shading.LightSample;
import glint.shading.Lights;
import glint.shading.Materials;
import glint.shading.Surface;

/**
 * The seed's model (SPEC section 4): ka ambient x colour + the sum over lights of (kd colour E n.l
 * + ks E (r.v)^shininess), + ks I_reflected + kt colour I_transmitted, with ka = kd. A shadow ray
 * passes kt of the light through each glass object it meets.
 */
final class Phong implements ShadingModel {

    @Override
    public void shade(Integrator it, PathVertex v, double dx, double dy, double dz, int hitsLeft, double weight) {
        direct(it, v, dx, dy, dz);
        boundary(it, v);
        it.scatter(v, dx, dy, dz, hitsLeft, weight);
        v.radiance.set(v.sum.r, v.sum.g, v.sum.b);
    }

    /** Ambient, and per light the diffuse term and the highlight, through what the shadow ray passes. */
    @Override
    public void direct(Integrator it, PathVertex v, double dx, double dy, double dz) {
        Surface s = v.surface;
        Materials m = it.materials;
        int material = s.material;
        double diffuseR = it.ambientR(), diffuseG = it.ambientG(), diffuseB = it.ambientB();
        double specR = 0, specG = 0, specB = 0;
        LightSample light = v.light;
        Lights lights = it.lights;
        for (int i = 0; i < lights.count(); i++) {
            double cosLight = lights.sample(i, s.px, s.py, s.pz, s.nx, s.ny, s.nz, light);
            if (!(cosLight > 0)) { // NaN too: no light from an undefined direction
                continue;
            }
            double pass = it.transmittance(s, light, i);
            if (pass == 0) {
                continue;
            }
            diffuseR += pass * light.irradianceR * cosLight;
            diffuseG += pass * light.irradianceG * cosLight;
            diffuseB += pass * light.irradianceB * cosLight;
            double cosReflectView = Bsdf.phongCosReflectView(s, light, cosLight, dx, dy, dz);
            if (cosReflectView > 0) {
                double highlight = pass * Math.pow(cosReflectView, m.shininess(material));
                specR += highlight * light.irradianceR;
                specG += highlight * light.irradianceG;
                specB += highlight * light.irradianceB;
            }
        }
        double kd = m.kd(material), ks = m.ks(material);
        v.sum.set(kd * m.color(material, 0) * diffuseR + ks * specR, kd * m.color(material, 1) * diffuseG + ks * specG,
                kd * m.color(material, 2) * diffuseB + ks * specB);
    }

    /** ks of the light reflected, kt x colour of the light refracted, whatever the angle. */
    @Override
    public void boundary(Integrator it, PathVertex v) {
        Materials m = it.materials;
        int material = v.surface.material;
        double kt = m.kt(material);
        v.eta = Bsdf.eta(m.ior(material), v.surface.front);
        v.reflect = m.ks(material);
        v.transmitR = kt * m.color(material, 0);
        v.transmitG = kt * m.color(material, 1);
        v.transmitB = kt * m.color(material, 2);
    }
}
