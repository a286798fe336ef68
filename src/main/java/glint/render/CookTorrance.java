package glint.render;

import glint.shading.Bsdf;
import glint.shading.LightSample;
import glint.shading.Lights;
import glint.shading.Materials;
import glint.shading.Rgb;
import glint.shading.Surface;

/**
 * The physically based model (SPEC section 4): Lambert matte, conductor metal (a mirror weighted
 * by Schlick's Fresnel plus a GGX highlight), dielectric glass (Fresnel-weighted reflection and
 * tinted refraction). Shadows are hard; glass blocks light.
 */
final class CookTorrance implements ShadingModel {

    @Override
    public void shade(Integrator it, PathVertex v, double dx, double dy, double dz, int hitsLeft, double weight) {
        switch (it.materials.type(v.surface.material)) {
            case MATTE -> matte(it, v);
            case METAL -> metal(it, v, dx, dy, dz, hitsLeft, weight);
            case GLASS -> glass(it, v, dx, dy, dz, hitsLeft, weight);
        }
    }

    /** Lambert: albedo / pi x E x cos for each light the point sees, plus ambient x albedo. */
    private static void matte(Integrator it, PathVertex v) {
        Surface s = v.surface;
        LightSample light = v.light;
        Lights lights = it.lights;
        Rgb sum = v.sum;
        sum.set(0, 0, 0);
        for (int i = 0; i < lights.count(); i++) {
            double cosLight = lights.sample(i, s.px, s.py, s.pz, s.nx, s.ny, s.nz, light);
            if (cosLight > 0 && it.transmittance(s, light, i) > 0) {
                sum.r += light.irradianceR * cosLight;
                sum.g += light.irradianceG * cosLight;
                sum.b += light.irradianceB * cosLight;
            }
        }
        Materials m = it.materials;
        int material = s.material;
        v.radiance.set(Bsdf.lambert(m.color(material, 0), sum.r, it.ambientR()),
                Bsdf.lambert(m.color(material, 1), sum.g, it.ambientG()),
                Bsdf.lambert(m.color(material, 2), sum.b, it.ambientB()));
    }

    /** A conductor: a GGX highlight from each light it sees when rough, plus the mirror weighted by Schlick's Fresnel. */
    private static void metal(Integrator it, PathVertex v, double dx, double dy, double dz, int hitsLeft,
                              double weight) {
        Surface s = v.surface;
        Materials m = it.materials;
        int material = s.material;
        Rgb sum = v.sum;
        sum.set(0, 0, 0);
        if (m.alpha(material) > 0 && s.cosIncident > 0) {
            LightSample light = v.light;
            Lights lights = it.lights;
            for (int i = 0; i < lights.count(); i++) {
                double cosLight = lights.sample(i, s.px, s.py, s.pz, s.nx, s.ny, s.nz, light);
                if (cosLight > 0 && it.transmittance(s, light, i) > 0) {
                    Bsdf.addConductorHighlight(m, material, s, light, cosLight, dx, dy, dz, sum);
                }
            }
        }
        if (hitsLeft > 1) {
            double fR = Bsdf.conductorFresnel(m.color(material, 0), s.cosIncident);
            double fG = Bsdf.conductorFresnel(m.color(material, 1), s.cosIncident);
            double fB = Bsdf.conductorFresnel(m.color(material, 2), s.cosIncident);
            double childWeight = weight * Math.max(fR, Math.max(fG, fB));
            double keep = it.keep(childWeight);
            if (keep > 0) {
                Rgb mirrored = it.traceReflected(s, dx, dy, dz, hitsLeft, childWeight * keep);
                sum.r += keep * fR * mirrored.r;
                sum.g += keep * fG * mirrored.g;
                sum.b += keep * fB * mirrored.b;
            }
        }
        v.radiance.set(sum.r, sum.g, sum.b);
    }

    /** A smooth dielectric: reflection and tinted refraction weighted by the Fresnel reflectance. */
    private static void glass(Integrator it, PathVertex v, double dx, double dy, double dz, int hitsLeft,
                              double weight) {
        Surface s = v.surface;
        Rgb sum = v.sum;
        sum.set(0, 0, 0);
        if (hitsLeft > 1) {
            Materials m = it.materials;
            int material = s.material;
            double eta = Bsdf.eta(m.ior(material), s.front);
            double reflectance = Bsdf.dielectricReflectance(s.cosIncident, eta, it.exactFresnel);
            it.addReflected(s, dx, dy, dz, hitsLeft, weight, reflectance, sum);
            double tR = (1 - reflectance) * m.color(material, 0);
            double tG = (1 - reflectance) * m.color(material, 1);
            double tB = (1 - reflectance) * m.color(material, 2);
            double childWeight = weight * Math.max(tR, Math.max(tG, tB));
            double keepRefracted = reflectance < 1 ? it.keep(childWeight) : 0;
            if (keepRefracted > 0) {
                Rgb refracted = it.traceRefracted(v, dx, dy, dz, eta, hitsLeft, childWeight * keepRefracted);
                sum.r += keepRefracted * tR * refracted.r;
                sum.g += keepRefracted * tG * refracted.g;
                sum.b += keepRefracted * tB * refracted.b;
            }
        }
        v.radiance.set(sum.r, sum.g, sum.b);
    }
}
