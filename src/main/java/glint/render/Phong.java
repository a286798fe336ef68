package glint.render;

import glint.shading.Bsdf;
import glint.shading.LightSample;
import glint.shading.Lights;
import glint.shading.Materials;
import glint.shading.Rgb;
import glint.shading.Surface;

/**
 * The seed's model (SPEC section 4): ka ambient x colour + the sum over lights of (kd colour E n.l
 * + ks E (r.v)^shininess), + ks I_reflected + kt colour I_transmitted, with ka = kd. A shadow ray
 * passes kt of the light through each glass object it meets.
 */
final class Phong implements ShadingModel {

    @Override
    public void shade(Integrator it, PathVertex v, double dx, double dy, double dz, int hitsLeft, double weight) {
        Surface s = v.surface;
        Materials m = it.materials;
        int material = s.material;
        double colorR = m.color(material, 0), colorG = m.color(material, 1), colorB = m.color(material, 2);
        double kd = m.kd(material), ks = m.ks(material), kt = m.kt(material);
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
        Rgb sum = v.sum;
        sum.set(kd * colorR * diffuseR + ks * specR, kd * colorG * diffuseG + ks * specG,
                kd * colorB * diffuseB + ks * specB);
        if (hitsLeft > 1) {
            it.addReflected(s, dx, dy, dz, hitsLeft, weight, ks, sum);
            double childWeight = weight * kt * Math.max(colorR, Math.max(colorG, colorB));
            double keepRefracted = childWeight > 0 ? it.keep(childWeight) : 0;
            if (keepRefracted > 0) {
                Rgb refracted = it.traceRefracted(v, dx, dy, dz, Bsdf.eta(m.ior(material), s.front), hitsLeft,
                        childWeight * keepRefracted);
                double k = keepRefracted * kt;
                sum.r += k * colorR * refracted.r;
                sum.g += k * colorG * refracted.g;
                sum.b += k * colorB * refracted.b;
            }
        }
        v.radiance.set(sum.r, sum.g, sum.b);
    }
}
