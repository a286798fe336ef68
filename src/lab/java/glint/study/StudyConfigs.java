package glint.study;

import glint.config.Shading;
import glint.render.RenderSettings.GlassFresnel;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;

/**
 * The configurations the speed/accuracy study measures: each knob swept on its own from the shipped
 * default (depth, samples, pruning weight, the plain cut-off instead of roulette, shading model, glass
 * Fresnel), plus a few combinations, among them the earlier defaults (depth 5, cut-off at 0.01).
 */
public final class StudyConfigs {

    private StudyConfigs() {
    }

    public static List<StudyConfig> full() {
        LinkedHashSet<StudyConfig> all = new LinkedHashSet<>();
        StudyConfig shipped = StudyConfig.shipped();
        all.add(shipped);
        for (int depth : new int[] {1, 2, 3, 5, 8, 12, 24}) {
            all.add(StudyConfig.ct(depth, shipped.samples(), shipped.minWeight()));
        }
        for (int samples : new int[] {1, 9, 16, 64}) {
            all.add(StudyConfig.ct(shipped.depth(), samples, shipped.minWeight()));
        }
        for (double weight : new double[] {1e-3, 1e-2, 3e-2, 1e-1}) { // the shipped one is already in
            all.add(StudyConfig.ct(shipped.depth(), shipped.samples(), weight));
        }
        all.add(shipped.cutOff());
        all.add(shipped.withFresnel(GlassFresnel.SCHLICK));
        all.add(shipped.withShading(Shading.PHONG));
        all.add(StudyConfig.ct(5, 4, 1e-2).cutOff()); // the earlier default
        all.add(StudyConfig.ct(5, 1, 1e-2).cutOff());
        all.add(StudyConfig.ct(5, 16, 1e-2).cutOff());
        all.add(StudyConfig.ct(8, 1, 1e-2));
        all.add(StudyConfig.ct(12, 16, 1e-2));
        all.add(StudyConfig.ct(16, 16, 3e-2));
        return new ArrayList<>(all);
    }

    /**
     * A smaller set for a short run, each knob swept from the shipped default as in {@link #full}:
     * no 64-sample point.
     */
    public static List<StudyConfig> quick() {
        StudyConfig shipped = StudyConfig.shipped();
        int depth = shipped.depth(), samples = shipped.samples();
        double weight = shipped.minWeight();
        List<StudyConfig> list = new ArrayList<>();
        list.add(shipped);
        list.add(StudyConfig.ct(1, samples, weight));
        list.add(StudyConfig.ct(3, samples, weight));
        list.add(StudyConfig.ct(5, samples, weight));
        list.add(StudyConfig.ct(depth, 1, weight));
        list.add(StudyConfig.ct(depth, 16, weight));
        list.add(StudyConfig.ct(depth, samples, 1e-3));
        list.add(StudyConfig.ct(depth, samples, 1e-1));
        list.add(shipped.cutOff());
        list.add(shipped.withFresnel(GlassFresnel.SCHLICK));
        list.add(shipped.withShading(Shading.PHONG));
        return list;
    }
}
