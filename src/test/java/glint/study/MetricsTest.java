package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.render.FrameBuffer;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Relative MSE, the Pareto front and the labels of the speed/accuracy study. */
class MetricsTest {

    @Test
    void relativeMseFollowsTheReferenceReadme() {
        FrameBuffer a = new FrameBuffer(2, 1), r = new FrameBuffer(2, 1);
        r.set(0, 0, 0, 0, 0);
        r.set(1, 0, 1, 1, 1);
        a.set(0, 0, 0.1, 0.1, 0.1);
        a.set(1, 0, 1, 1, 1.5);
        // channels: 3 x 0.01 / 0.01, then 0, 0, 0.25 / 1.01; mean over 6
        double expected = (3 * (0.1f * 0.1f) / 0.01 + 0.25 / 1.01) / 6;
        assertEquals(expected, RelativeMse.of(a, r), 1e-6);
        assertEquals(0, RelativeMse.of(r, r));
        assertThrows(IllegalArgumentException.class, () -> RelativeMse.of(a, new FrameBuffer(1, 2)));
    }

    @Test
    void paretoFrontKeepsOnlyPointsNothingBeatsOnBoth() {
        double[] cost = {10, 5, 20, 7, 30, 6};
        double[] error = {1, 3, 0.5, 3.5, 0.6, 2};
        // 5 (3) -> 6 (2) -> 10 (1) -> 20 (0.5); 7 is beaten by 6, 30 by 20
        assertEquals(List.of(1, 5, 0, 2), Pareto.front(cost, error));
    }

    @Test
    void paretoToleranceDropsGainsBelowIt() {
        double[] cost = {1, 2, 3};
        double[] error = {1.0, 0.99, 0.5};
        assertEquals(List.of(0, 1, 2), Pareto.front(cost, error, 0));
        assertEquals(List.of(0, 2), Pareto.front(cost, error, 0.02));
    }

    @Test
    void shippedConfigIsTheAppDefaultAndSweepsTurnOneKnob() {
        StudyConfig shipped = StudyConfig.shipped();
        glint.config.Config defaults = glint.config.Config.defaults();
        assertEquals(defaults.recursionMax(), shipped.depth());
        assertEquals(defaults.samples(), shipped.samples());
        assertEquals(defaults.minWeight(), shipped.minWeight());
        assertEquals(StudyConfig.Knob.NONE, shipped.knob());
        assertEquals(StudyConfig.Knob.DEPTH, StudyConfig.ct(2, shipped.samples(), shipped.minWeight()).knob());
        assertEquals(StudyConfig.Knob.SEVERAL, StudyConfig.ct(2, 16, shipped.minWeight()).knob());
        assertEquals("d16 s4 w1e-2", shipped.label());
        assertEquals("d16 s4 w1e-2 cut", shipped.cutOff().label());
        assertEquals(StudyConfig.Knob.PRUNING, shipped.cutOff().knob());
        assertEquals("cut", shipped.cutOff().knobLabel());
        assertEquals("w1e-3", StudyConfig.ct(16, 4, 1e-3).knobLabel());
        assertEquals("shipped", shipped.knobLabel());
        assertEquals(StudyConfigs.full().size(), new java.util.HashSet<>(StudyConfigs.full()).size());
        assertEquals(24, StudyConfigs.full().size());
    }

    /** The short run's configurations are points of the full one: each knob swept from the shipped default. */
    @Test
    void theQuickSetIsPartOfTheFullOne() {
        List<StudyConfig> full = StudyConfigs.full();
        for (StudyConfig config : StudyConfigs.quick()) {
            assertTrue(full.contains(config), config.label());
            assertTrue(config.knob() != StudyConfig.Knob.SEVERAL, config.label());
        }
    }

    @Test
    void numbersAreWrittenCompactly() {
        assertEquals("1e-9", Numbers.sci(1e-9));
        assertEquals("2.5e-4", Numbers.sci(2.5e-4));
        assertEquals("1e-1", Numbers.sci(0.1));
        assertEquals("0", Numbers.sci(0));
    }
}
