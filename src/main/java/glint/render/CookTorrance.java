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
        direct(it, v, dx, dy, dz);
        switch (it.materials.type(v.surface.material)) {
            case MATTE -> { }
            case METAL -> mirror(it, v, dx, dy, dz, hitsLeft, weight);
            case GLASS -> {
                boundary(it, v);
                it.scatter(v, dx, dy, dz, hitsLeft, weight);
            }
        }
        v.radiance.set(v.sum.r, v.sum.g, v.sum.b);
    }

    /** Lambert's term for matte, the GGX highlight for rough metal, nothing for glass. */
    @Override
    public void direct(Integrator it, PathVertex v, double dx, double dy, double dz) {
        switch (it.materials.type(v.surface.material)) {
            case MATTE -> matte(it, v);
            case METAL -> highlight(it, v, dx, dy, dz);
            case GLASS -> v.sum.set(0, 0, 0);
        }
    }

    /** A smooth dielectric: the Fresnel reflectance, and the rest tinted by the glass's colour. */
    @Override
    public void boundary(Integrator it, PathVertex v) {
        Surface s = v.surface;
        Materials m = it.materials;
        int material = s.material;
        v.eta = Bsdf.eta(m.ior(material), s.front);
        double reflectance = Bsdf.dielectricReflectance(s.cosIncident, v.eta, it.exactFresnel);
        v.reflect = reflectance;
        v.transmitR = (1 - reflectance) * m.color(material, 0);
        v.transmitG = (1 - reflectance) * m.color(material, 1);
        v.transmitB = (1 - reflectance) * m.color(material, 2);
    }

    /** Lambert: albedo / pi x E x cos for each light the point sees, plus ambient x albedo. */
    private static void matte(Integrator it, PathVertex v) {
        Surface s = v.surface;
        LightSample light = v.light;
        Lights lights = it.lights;
        double irradianceR = 0, irradianceG = 0, irradianceB = 0;
        for (int i = 0; i < lights.count(); i++) {
            double cosLight = lights.sample(i, s.px, s.py, s.pz, s.nx, s.ny, s.nz, light);
            if (cosLight > 0 && it.transmittance(s, light, i) > 0) {
                irradianceR += light.irradianceR * cosLight;
                irradianceG += light.irradianceG * cosLight;
                irradianceB += light.irradianceB * cosLight;
            }
        }
        Materials m = it.materials;
        int material = s.material;
        v.sum.set(Bsdf.lambert(m.color(material, 0), irradianceR, it.ambientR()),
                Bsdf.lambert(m.color(material, 1), irradianceG, it.ambientG()),
                Bsdf.lambert(m.color(material, 2), irradianceB, it.ambientB()));
    }

    /** A conductor's GGX highlight from each light it sees, when rough. */
    private static void highlight(Integrator it, PathVertex v, double dx, double dy, double dz) {
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
    }

    /** A conductor's mirror, weighted by Schlick's Fresnel per channel, added to {@code v.sum}. */
    private static void mirror(Integrator it, PathVertex v, double dx, double dy, double dz, int hitsLeft,
                               double weight) {
        if (hitsLeft <= 1) {
            return;
        }
        Surface s = v.surface;
        Materials m = it.materials;
        int material = s.material;
        Rgb sum = v.sum;
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
}
