package glint.study;

import glint.config.Shading;
import glint.render.RenderSettings.GlassFresnel;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;

/**
 * The configurations the speed/accuracy study measures: each knob swept on its own from the shipped
 * default (depth, samples, pruning weight, shading model, glass Fresnel), plus a few combinations.
 */
public final class StudyConfigs {

    private StudyConfigs() {
    }

    public static List<StudyConfig> full() {
        LinkedHashSet<StudyConfig> all = new LinkedHashSet<>();
        StudyConfig shipped = StudyConfig.shipped();
        all.add(shipped);
        for (int depth : new int[] {1, 2, 3, 4, 6, 8}) {
            all.add(StudyConfig.ct(depth, shipped.samples(), shipped.minWeight()));
        }
        for (int samples : new int[] {1, 9, 16, 64}) {
            all.add(StudyConfig.ct(shipped.depth(), samples, shipped.minWeight()));
        }
        for (double weight : new double[] {0, 1e-3, 1e-2, 1e-1}) { // the shipped one is already in
            all.add(StudyConfig.ct(shipped.depth(), shipped.samples(), weight));
        }
        all.add(shipped.withFresnel(GlassFresnel.SCHLICK));
        all.add(shipped.withShading(Shading.PHONG));
        all.add(StudyConfig.ct(3, 1, 1e-2));
        all.add(StudyConfig.ct(4, 1, 1e-3));
        all.add(StudyConfig.ct(3, 16, 1e-3));
        all.add(StudyConfig.ct(6, 16, 1e-3));
        all.add(StudyConfig.ct(8, 16, 0));
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
        list.add(StudyConfig.ct(8, samples, weight));
        list.add(StudyConfig.ct(depth, 1, weight));
        list.add(StudyConfig.ct(depth, 16, weight));
        list.add(StudyConfig.ct(depth, samples, 0));
        list.add(StudyConfig.ct(depth, samples, 1e-3));
        list.add(shipped.withFresnel(GlassFresnel.SCHLICK));
        list.add(shipped.withShading(Shading.PHONG));
        return list;
    }
}
