package glint.recipe;

import glint.shading.Bsdf;
import glint.shading.BsdfSample;
import glint.shading.Materials;
import glint.shading.Rgb;
import glint.shading.Surface;

/**
 * The BSDF of a material type added by the recipe of docs/architecture.md, in test sources only: a
 * surface that sends back its colour times its strength as radiance, whatever lights it, and sends no
 * rays on. {@link GlowType} registers it and compiles a material's strength, the one number it reads.
 */
final class Glow implements Bsdf {

    /** Where its material's strength stands among its numbers ({@link Materials#parameter}). */
    private static final int STRENGTH = 0;

    @Override
    public boolean emits() {
        return true;
    }

    /** Its colour times its strength, whatever lights it. */
    @Override
    public void emitted(Materials m, Surface s, Rgb out) {
        double strength = m.parameter(s.material, STRENGTH);
        out.set(strength * m.color(s.material, 0), strength * m.color(s.material, 1),
                strength * m.color(s.material, 2));
    }

    /** It reflects nothing: no lobe to evaluate or sample. */
    @Override
    public void evaluate(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY,
                         double wiZ, Rgb f) {
        f.set(0, 0, 0);
    }

    @Override
    public double pdf(Materials m, Surface s, double woX, double woY, double woZ, double wiX, double wiY,
                      double wiZ) {
        return 0;
    }

    @Override
    public boolean sample(Materials m, Surface s, double woX, double woY, double woZ, double u1, double u2,
                          double uLobe, BsdfSample out) {
        return false;
    }

    /** No lobe at all: no light sample sees it. */
    @Override
    public int lobes(Materials m, int material) {
        return 0;
    }
}
