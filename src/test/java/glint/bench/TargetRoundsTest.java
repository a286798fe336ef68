package glint.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.bench.TargetRounds.Rounds;
import glint.bench.TargetRounds.Run;
import glint.bench.TargetRounds.Target;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The targets table: the summary line read back, medians over rounds, per-round speed-ups, met or not. */
class TargetRoundsTest {

    @Test
    void readsTheSummaryLineAndTheMedianRenderCpuOfTheFrames() {
        Run run = TargetRounds.parse("""
                frame 1: 40.00 ms, render cpu 79.50 ms
                frame 2: 41.53 ms, render cpu 81.00 ms
                frame 3: 45.00 ms, render cpu 80.50 ms
                bench: frames=3 median_ms=41.53 p95_ms=45.00 rays_per_s=29792358
                """);
        assertEquals(41.53, run.medianMillis());
        assertEquals(45.00, run.p95Millis());
        assertEquals(80.50, run.cpuMedianMillis());
    }

    @Test
    void framesWithoutRenderCpuLeaveItUnknown() {
        Run run = TargetRounds.parse("frame 1: 40.00 ms\nbench: frames=1 median_ms=40.00 p95_ms=40.00 rays_per_s=1\n");
        assertEquals(40.00, run.medianMillis());
        assertTrue(Double.isNaN(run.cpuMedianMillis()));
    }

    @Test
    void refusesAnyOtherLine() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> TargetRounds.parse("frame 3: 41.53 ms"));
        assertEquals("not a bench summary line: frame 3: 41.53 ms", e.getMessage());
    }

    @Test
    void theMedianOfAnOddAndAnEvenCount() {
        assertEquals(3, TargetRounds.median(new double[] {5, 1, 3}));
        assertEquals(2.5, TargetRounds.median(new double[] {4, 1, 3, 2}));
    }

    @Test
    void theTableGivesMediansOverRoundsTheSpeedUpOfEachRoundAndTheRenderCpu() {
        Target target = new Target("test scene", "scenes/bench/spec-example.yaml", 25); // at most 40 ms
        Rounds rounds = new Rounds(target,
                List.of(new Run(80, 100, 80), new Run(60, 90, 60), new Run(100, 120, 100)),
                List.of(new Run(40, 50, 84), new Run(30, 70, 62), new Run(50, 60, 110)));
        String table = TargetRounds.table(List.of(rounds));
        assertEquals("""
                | target | wanted | median of the rounds' medians (p95) | rounds | met |
                |---|---|---|---|---|
                | test scene, 2 threads | >= 25 fps (<= 40.0 ms) | 40.00 ms (60) = 25 fps | 40.0, 30.0, 50.0 | yes |
                | test scene, 2 threads over 1 | >= 1.9x | 2.000x | 2.00, 2.00, 2.00 | yes |

                | render CPU a frame | 1 thread | 2 threads | 2 threads over 1 on two free cores |
                |---|---|---|---|
                | test scene | 80.00 ms | 84.00 ms | 1.905x |
                """, table);
    }

    @Test
    void aTargetMissedByAHairIsNotMet() {
        Target target = new Target("test scene", "scenes/bench/spec-example.yaml", 25);
        Rounds rounds = new Rounds(target, List.of(new Run(75.9, 80, Double.NaN)), List.of(new Run(40.01, 45, Double.NaN)));
        String table = TargetRounds.table(List.of(rounds));
        assertEquals("""
                | target | wanted | median of the rounds' medians (p95) | rounds | met |
                |---|---|---|---|---|
                | test scene, 2 threads | >= 25 fps (<= 40.0 ms) | 40.01 ms (45) = 25 fps | 40.0 | no |
                | test scene, 2 threads over 1 | >= 1.9x | 1.897x | 1.90 | no |
                """, table);
    }
}
