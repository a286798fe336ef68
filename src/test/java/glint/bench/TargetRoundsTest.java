package glint.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import glint.bench.TargetRounds.Rounds;
import glint.bench.TargetRounds.Run;
import glint.bench.TargetRounds.Target;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The targets table: the summary line read back, medians over rounds, per-round speed-ups, met or not. */
class TargetRoundsTest {

    @Test
    void readsTheBenchSummaryLine() {
        Run run = TargetRounds.parse("bench: frames=60 median_ms=41.53 p95_ms=134.70 rays_per_s=29792358");
        assertEquals(41.53, run.medianMillis());
        assertEquals(134.70, run.p95Millis());
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
    void theTableGivesMediansOverRoundsAndTheSpeedUpOfEachRound() {
        Target target = new Target("test scene", "scenes/default.yaml", 25); // at most 40 ms
        Rounds rounds = new Rounds(target,
                List.of(new Run(80, 100), new Run(60, 90), new Run(100, 120)),
                List.of(new Run(40, 50), new Run(30, 70), new Run(50, 60)));
        String table = TargetRounds.table(List.of(rounds));
        assertEquals("""
                | target | wanted | median of the rounds' medians (p95) | rounds | met |
                |---|---|---|---|---|
                | test scene, 2 threads | >= 25 fps (<= 40.0 ms) | 40.00 ms (60) = 25 fps | 40.0, 30.0, 50.0 | yes |
                | test scene, 2 threads over 1 | >= 1.9x | 2.000x | 2.00, 2.00, 2.00 | yes |
                """, table);
    }

    @Test
    void aTargetMissedByAHairIsNotMet() {
        Target target = new Target("test scene", "scenes/default.yaml", 25);
        Rounds rounds = new Rounds(target, List.of(new Run(75.9, 80)), List.of(new Run(40.01, 45)));
        String table = TargetRounds.table(List.of(rounds));
        assertEquals("""
                | target | wanted | median of the rounds' medians (p95) | rounds | met |
                |---|---|---|---|---|
                | test scene, 2 threads | >= 25 fps (<= 40.0 ms) | 40.01 ms (45) = 25 fps | 40.0 | no |
                | test scene, 2 threads over 1 | >= 1.9x | 1.897x | 1.90 | no |
                """, table);
    }
}
