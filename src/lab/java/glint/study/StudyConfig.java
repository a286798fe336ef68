package glint.study;

import glint.config.Config;
import glint.render.LightTransport;
import glint.render.RenderSettings.GlassFresnel;
import glint.render.RenderSettings.Pruning;
import glint.render.RenderSettings;
import glint.render.Shading;

/**
 * One method of the speed/accuracy study: an integrator with its depth and samples, and the knobs
 * of Whitted's that trade render time for accuracy.
 *
 * @param transport Whitted's integrator (depth 1: ray casting), the path tracer or the bidirectional one
 * @param shading   cook-torrance (the reference model) or phong
 * @param depth     recursion_max
 * @param samples   stratified samples per pixel (a perfect square)
 * @param minWeight the path weight below which Whitted's rays are pruned (the path tracer ignores it)
 * @param fresnel   glass Fresnel: exact or Schlick
 * @param pruning   Russian roulette below minWeight (Glint's) or the plain cut-off
 */
public record StudyConfig(LightTransport transport, Shading shading, int depth, int samples, double minWeight,
                          GlassFresnel fresnel, Pruning pruning) {

    /** Depth of the converged images. */
    public static final int REFERENCE_DEPTH = 64;
    /** Whitted's converged image: rays below this weight are cut off, a loss no 8-bit image shows. */
    public static final double REFERENCE_MIN_WEIGHT = 1e-4;

    public StudyConfig(Shading shading, int depth, int samples, double minWeight, GlassFresnel fresnel,
                       Pruning pruning) {
        this(LightTransport.WHITTED, shading, depth, samples, minWeight, fresnel, pruning);
    }

    public StudyConfig(Shading shading, int depth, int samples, double minWeight, GlassFresnel fresnel) {
        this(shading, depth, samples, minWeight, fresnel, Pruning.ROULETTE);
    }

    /** Whitted's converged image: cook-torrance, exact Fresnel, depth 64, rays below weight 1e-4 cut off. */
    public static StudyConfig reference(int samples) {
        return new StudyConfig(Shading.COOK_TORRANCE, REFERENCE_DEPTH, samples, REFERENCE_MIN_WEIGHT,
                GlassFresnel.EXACT, Pruning.CUTOFF);
    }

    /** The converged path-traced image, the physically based reference: depth 64. */
    public static StudyConfig pathReference(int samples) {
        return path(REFERENCE_DEPTH, samples);
    }

    /** What Glint ships in config.properties (and Config.defaults()): Whitted's integrator. */
    public static StudyConfig shipped() {
        Config c = Config.defaults();
        return new StudyConfig(c.shading(), c.recursionMax(), c.samples(), c.minWeight(), GlassFresnel.EXACT);
    }

    /** Whitted's integrator with cook-torrance at the given depth, samples and pruning weight. */
    public static StudyConfig ct(int depth, int samples, double minWeight) {
        return new StudyConfig(Shading.COOK_TORRANCE, depth, samples, minWeight, GlassFresnel.EXACT);
    }

    /** Whitted's integrator as shipped but for its depth and samples (depth 1: ray casting). */
    public static StudyConfig whitted(int depth, int samples) {
        return ct(depth, samples, shipped().minWeight());
    }

    /** The path tracer at the shipped depth, as {@code --integrator path} renders. */
    public static StudyConfig path(int samples) {
        return path(shipped().depth(), samples);
    }

    /** The bidirectional path tracer at the shipped depth, as {@code --integrator bdpt} renders. */
    public static StudyConfig bdpt(int samples) {
        StudyConfig s = shipped();
        return new StudyConfig(LightTransport.BDPT, Shading.COOK_TORRANCE, s.depth(), samples, s.minWeight(),
                GlassFresnel.EXACT, Pruning.ROULETTE);
    }

    private static StudyConfig path(int depth, int samples) {
        StudyConfig s = shipped();
        return new StudyConfig(LightTransport.PATH, Shading.COOK_TORRANCE, depth, samples, s.minWeight(),
                GlassFresnel.EXACT, Pruning.ROULETTE);
    }

    public StudyConfig withShading(Shading model) {
        return new StudyConfig(transport, model, depth, samples, minWeight, fresnel, pruning);
    }

    public StudyConfig withFresnel(GlassFresnel f) {
        return new StudyConfig(transport, shading, depth, samples, minWeight, f, pruning);
    }

    /** The same with the plain cut-off instead of Russian roulette below minWeight. */
    public StudyConfig cutOff() {
        return new StudyConfig(transport, shading, depth, samples, minWeight, fresnel, Pruning.CUTOFF);
    }

    public boolean isPath() {
        return transport == LightTransport.PATH;
    }

    /** Whether it solves the rendering equation: the path tracer or the bidirectional one. */
    public boolean isPhysical() {
        return transport.physical();
    }

    /** The method's family: ray casting (Whitted at depth 1), Whitted, path or bdpt. */
    public Method method() {
        return transport == LightTransport.BDPT ? Method.BDPT : isPath() ? Method.PATH
                : depth == 1 ? Method.RAY_CASTING : Method.WHITTED;
    }

    /** The families of methods, each with its name in the charts and tables. */
    public enum Method {
        RAY_CASTING("ray casting"), WHITTED("Whitted"), PATH("path"), BDPT("bdpt");

        private final String title;

        Method(String title) {
            this.title = title;
        }

        public String title() {
            return title;
        }
    }

    /** Which knob this configuration turns away from the shipped default (the default itself: none). */
    public Knob knob() {
        StudyConfig d = shipped();
        if (transport != d.transport) {
            return Knob.TRANSPORT;
        }
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

    /** The knobs of the study; {@link #TRANSPORT}: the path tracer instead of Whitted's integrator. */
    public enum Knob { NONE, DEPTH, SAMPLES, MIN_WEIGHT, SHADING, FRESNEL, PRUNING, TRANSPORT, SEVERAL }

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
            case TRANSPORT, SEVERAL -> label();
        };
    }

    public RenderSettings settings() {
        return new RenderSettings(shading, depth, minWeight, Config.defaults().epsilon()).withGlassFresnel(fresnel)
                .withPruning(pruning).withTransport(transport);
    }

    /**
     * Short label: "d16 s4 w1e-2", plus "phong" or "schlick" when they differ from the reference model,
     * and "cut" for the plain cut-off; the path tracer's: "path d16 s64".
     */
    public String label() {
        if (isPhysical()) {
            return transport.key() + " d" + depth + " s" + samples;
        }
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

    /** The method as a user names it: "ray casting s4", "Whitted d8 s4", "path s64" (at the shipped depth). */
    public String methodLabel() {
        return switch (method()) {
            case RAY_CASTING -> "ray casting s" + samples;
            case WHITTED -> "Whitted d" + depth + " s" + samples;
            case PATH -> "path s" + samples + (depth == shipped().depth() ? "" : " d" + depth);
            case BDPT -> "bdpt s" + samples + (depth == shipped().depth() ? "" : " d" + depth);
        };
    }

    @Override
    public String toString() {
        return label();
    }
}
