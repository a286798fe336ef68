package glint.study;

import glint.config.Config;
import glint.config.Shading;
import glint.render.RenderSettings;
import glint.render.RenderSettings.GlassFresnel;
import glint.render.RenderSettings.Pruning;

/**
 * One point of the speed/accuracy study: the knobs that trade render time for accuracy.
 *
 * @param shading   cook-torrance (the reference model) or phong
 * @param depth     recursion_max
 * @param samples   stratified samples per pixel (a perfect square)
 * @param minWeight the path weight below which rays are pruned
 * @param fresnel   glass Fresnel: exact or Schlick
 * @param pruning   Russian roulette below minWeight (Glint's) or the plain cut-off
 */
public record StudyConfig(Shading shading, int depth, int samples, double minWeight, GlassFresnel fresnel,
                          Pruning pruning) {

    /** Depth of the converged image. */
    public static final int REFERENCE_DEPTH = 64;
    /** The converged image's plain cut-off: a loss no 8-bit image shows. */
    public static final double REFERENCE_MIN_WEIGHT = 1e-4;

    public StudyConfig(Shading shading, int depth, int samples, double minWeight, GlassFresnel fresnel) {
        this(shading, depth, samples, minWeight, fresnel, Pruning.ROULETTE);
    }

    /** The converged image: cook-torrance, exact Fresnel, depth 64, rays below weight 1e-4 cut off. */
    public static StudyConfig reference(int samples) {
        return new StudyConfig(Shading.COOK_TORRANCE, REFERENCE_DEPTH, samples, REFERENCE_MIN_WEIGHT,
                GlassFresnel.EXACT, Pruning.CUTOFF);
    }

    /** What Glint ships in config.properties (and Config.defaults()). */
    public static StudyConfig shipped() {
        Config c = Config.defaults();
        return new StudyConfig(c.shading(), c.recursionMax(), c.samples(), c.minWeight(), GlassFresnel.EXACT);
    }

    public static StudyConfig ct(int depth, int samples, double minWeight) {
        return new StudyConfig(Shading.COOK_TORRANCE, depth, samples, minWeight, GlassFresnel.EXACT);
    }

    public StudyConfig withShading(Shading model) {
        return new StudyConfig(model, depth, samples, minWeight, fresnel, pruning);
    }

    public StudyConfig withFresnel(GlassFresnel f) {
        return new StudyConfig(shading, depth, samples, minWeight, f, pruning);
    }

    /** The same with the plain cut-off instead of Russian roulette below minWeight. */
    public StudyConfig cutOff() {
        return new StudyConfig(shading, depth, samples, minWeight, fresnel, Pruning.CUTOFF);
    }

    /** Which knob this configuration turns away from the shipped default (the default itself: none). */
    public Knob knob() {
        StudyConfig d = shipped();
        int differences = (shading != d.shading ? 1 : 0) + (depth != d.depth ? 1 : 0) + (samples != d.samples ? 1 : 0)
                + (minWeight != d.minWeight ? 1 : 0) + (fresnel != d.fresnel ? 1 : 0) + (pruning != d.pruning ? 1 : 0);
        if (differences == 0) {
            return Knob.NONE;
        }
        if (differences > 1) {
            return Knob.SEVERAL;
        }
        if (depth != d.depth) {
            return Knob.DEPTH;
        }
        if (samples != d.samples) {
            return Knob.SAMPLES;
        }
        if (minWeight != d.minWeight) {
            return Knob.MIN_WEIGHT;
        }
        if (pruning != d.pruning) {
            return Knob.PRUNING;
        }
        return shading != d.shading ? Knob.SHADING : Knob.FRESNEL;
    }

    /** The knobs of the study. */
    public enum Knob { NONE, DEPTH, SAMPLES, MIN_WEIGHT, SHADING, FRESNEL, PRUNING, SEVERAL }

    /** The value of the knob this configuration turns, for a point label: "d3", "s16", "w1e-2", "phong". */
    public String knobLabel() {
        return switch (knob()) {
            case DEPTH -> "d" + depth;
            case SAMPLES -> "s" + samples;
            case MIN_WEIGHT -> "w" + Numbers.sci(minWeight);
            case SHADING -> "phong";
            case FRESNEL -> "schlick";
            case PRUNING -> "cut";
            case NONE -> "shipped";
            case SEVERAL -> label();
        };
    }

    public RenderSettings settings() {
        return new RenderSettings(shading, depth, minWeight, Config.defaults().epsilon()).withGlassFresnel(fresnel)
                .withPruning(pruning);
    }

    /**
     * Short label: "d16 s4 w1e-2", plus "phong" or "schlick" when they differ from the reference model,
     * and "cut" for the plain cut-off.
     */
    public String label() {
        StringBuilder b = new StringBuilder();
        b.append('d').append(depth).append(" s").append(samples).append(" w").append(Numbers.sci(minWeight));
        if (shading == Shading.PHONG) {
            b.append(" phong");
        }
        if (fresnel == GlassFresnel.SCHLICK) {
            b.append(" schlick");
        }
        if (pruning == Pruning.CUTOFF) {
            b.append(" cut");
        }
        return b.toString();
    }

    @Override
    public String toString() {
        return label();
    }
}
