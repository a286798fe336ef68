package glint.study;

import glint.render.RenderSettings.GlassFresnel;
import glint.render.Shading;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;

/**
 * The methods the speed/accuracy study measures. Against physics ({@link #methods}): ray casting
 * (Whitted at depth 1) at 1 to 64 samples, Whitted at depths 2 to 16 and at 1 to 64 samples, the
 * path tracer at 1 to 1024 samples, the bidirectional one at 1 to 256. Against Whitted's own converged image ({@link #whittedKnobs}):
 * besides depth and samples, Whitted's other knobs turned one at a time from the shipped default
 * (pruning weight, the plain cut-off, Schlick's glass Fresnel, the phong model).
 */
public final class StudyConfigs {

    private static final int[] RAY_CASTING_SAMPLES = {1, 4, 16, 64};
    private static final int[] WHITTED_DEPTHS = {2, 3, 5, 8, 16};
    private static final int[] WHITTED_SAMPLES = {1, 4, 16, 64};
    private static final int[] PATH_SAMPLES = {1, 4, 16, 64, 256, 1024};
    private static final int[] BDPT_SAMPLES = {1, 4, 16, 64, 256};

    private StudyConfigs() {
    }

    /** Every configuration of a full run: the methods, then Whitted's other knobs. */
    public static List<StudyConfig> full() {
        LinkedHashSet<StudyConfig> all = new LinkedHashSet<>(methods());
        all.addAll(whittedKnobs());
        return new ArrayList<>(all);
    }

    /** The methods compared against the converged path-traced image, cheapest family first. */
    public static List<StudyConfig> methods() {
        return methods(RAY_CASTING_SAMPLES, WHITTED_DEPTHS, WHITTED_SAMPLES, PATH_SAMPLES, BDPT_SAMPLES);
    }

    /** Whitted's knobs besides depth and samples, each turned alone from the shipped default. */
    public static List<StudyConfig> whittedKnobs() {
        StudyConfig shipped = StudyConfig.shipped();
        return List.of(StudyConfig.ct(shipped.depth(), shipped.samples(), 1e-3),
                StudyConfig.ct(shipped.depth(), shipped.samples(), 1e-1), shipped.cutOff(),
                shipped.withFresnel(GlassFresnel.SCHLICK), shipped.withShading(Shading.PHONG));
    }

    /**
     * Whether the configuration is measured against Whitted's own converged image: Whitted along
     * depth (at the shipped samples) and along samples (at the shipped depth), and its other knobs;
     * not the path tracer, nor ray casting at other samples than the shipped ones.
     */
    public static boolean againstWhitted(StudyConfig config) {
        StudyConfig shipped = StudyConfig.shipped();
        return !config.isPhysical() && (config.depth() != 1 || config.samples() == shipped.samples());
    }

    /**
     * A smaller set for a short run, every family still there: ray casting at 1 and 4 samples, Whitted
     * at depths 2 and 16 and at 1 sample, the path tracer at 1 to 64 samples, the bidirectional one at 1 to 16,
     * and the cut-off.
     */
    public static List<StudyConfig> quick() {
        List<StudyConfig> list = methods(new int[] {1, 4}, new int[] {2, 16}, new int[] {1}, new int[] {1, 4, 16, 64},
                new int[] {1, 4, 16});
        list.add(StudyConfig.shipped().cutOff());
        return list;
    }

    private static List<StudyConfig> methods(int[] rayCasting, int[] depths, int[] whittedSamples, int[] path,
                                             int[] bdpt) {
        LinkedHashSet<StudyConfig> all = new LinkedHashSet<>();
        StudyConfig shipped = StudyConfig.shipped();
        for (int samples : rayCasting) {
            all.add(StudyConfig.whitted(1, samples));
        }
        for (int depth : depths) {
            all.add(StudyConfig.whitted(depth, shipped.samples()));
        }
        for (int samples : whittedSamples) {
            all.add(StudyConfig.whitted(shipped.depth(), samples));
        }
        for (int samples : path) {
            all.add(StudyConfig.path(samples));
        }
        for (int samples : bdpt) {
            all.add(StudyConfig.bdpt(samples));
        }
        return new ArrayList<>(all);
    }
}
