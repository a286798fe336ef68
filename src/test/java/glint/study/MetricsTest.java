package glint.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
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
        assertEquals(28, StudyConfigs.full().size());
    }

    @Test
    void aMethodIsAnIntegratorWithItsDepthAndSamples() {
        StudyConfig path = StudyConfig.path(64);
        assertEquals(glint.render.LightTransport.PATH, path.settings().transport());
        assertEquals(StudyConfig.shipped().depth(), path.settings().recursionMax());
        assertEquals("path d16 s64", path.label());
        assertEquals("path s64", path.methodLabel());
        assertEquals(StudyConfig.Method.PATH, path.method());
        assertEquals(StudyConfig.Knob.TRANSPORT, path.knob());
        assertEquals("ray casting s4", StudyConfig.whitted(1, 4).methodLabel());
        assertEquals(StudyConfig.Method.RAY_CASTING, StudyConfig.whitted(1, 4).method());
        assertEquals("Whitted d8 s4", StudyConfig.whitted(8, 4).methodLabel());
        assertEquals(glint.render.LightTransport.WHITTED, StudyConfig.whitted(8, 4).settings().transport());
        assertEquals(64, StudyConfig.pathReference(4096).depth());
        assertEquals("path s4096 d64", StudyConfig.pathReference(4096).methodLabel());
        assertEquals("bdpt s16", StudyConfig.bdpt(16).methodLabel());
        assertEquals(StudyConfig.Method.BDPT, StudyConfig.bdpt(16).method());
        assertEquals(glint.render.LightTransport.BDPT, StudyConfig.bdpt(16).settings().transport());
    }

    /**
     * Every family of methods against physics: ray casting, Whitted along depth and samples, the path up to 1024
     * samples, bdpt up to 256.
     */
    @Test
    void theMethodsSpanEveryFamilyAndTheQuickSetIsPartOfTheFullOne() {
        List<StudyConfig> methods = StudyConfigs.methods();
        assertEquals(23, methods.size());
        assertTrue(methods.contains(StudyConfig.whitted(1, 1)));
        assertTrue(methods.contains(StudyConfig.whitted(2, 4)));
        assertTrue(methods.contains(StudyConfig.whitted(16, 64)));
        assertTrue(methods.contains(StudyConfig.path(1)));
        assertTrue(methods.contains(StudyConfig.path(1024)));
        assertTrue(methods.contains(StudyConfig.bdpt(1)));
        assertTrue(methods.contains(StudyConfig.bdpt(256)));
        assertTrue(methods.contains(StudyConfig.shipped()));
        List<StudyConfig> full = StudyConfigs.full();
        for (StudyConfig config : StudyConfigs.quick()) {
            assertTrue(full.contains(config), config.label());
        }
        for (StudyConfig.Method family : StudyConfig.Method.values()) {
            assertTrue(StudyConfigs.quick().stream().anyMatch(c -> c.method() == family), family.title());
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
