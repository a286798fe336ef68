package glint.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Method;
import java.net.URL;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.snakeyaml.engine.v2.api.Load;
import picocli.CommandLine;

/** Comparing two builds: the frame lines read back, the quantiles, and a build loaded on its own. */
class CompareBuildsTest {

    @Test
    void takesTheLeastRenderCpuAfterTheFirstFrame() {
        assertEquals(79.25, CompareBuilds.leastAfterFirst("""
                frame 1: 40.00 ms, render cpu 60.00 ms
                frame 2: 41.53 ms, render cpu 81.00 ms
                frame 3: 45.00 ms, render cpu 79.25 ms
                bench: frames=3 median_ms=41.53 p95_ms=45.00 rays_per_s=29792358
                """));
    }

    @Test
    void refusesOutputWithNoFrameAfterTheFirst() {
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> CompareBuilds.leastAfterFirst("frame 1: 40.00 ms, render cpu 60.00 ms\n"));
        assertEquals("no render cpu after the first frame in: frame 1: 40.00 ms, render cpu 60.00 ms", e.getMessage());
    }

    @Test
    void quantilesInterpolateBetweenSortedNeighbours() {
        double[] values = {4, 1, 3, 2};
        assertEquals(1, CompareBuilds.quantile(values, 0));
        assertEquals(1.75, CompareBuilds.quantile(values, 0.25));
        assertEquals(2.5, CompareBuilds.quantile(values, 0.5));
        assertEquals(4, CompareBuilds.quantile(values, 1));
        assertEquals(4, values[0], "the values are left in their order");
    }

    @Test
    void aMissingJarIsNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> CompareBuilds.mainOf(Path.of("target/no-such.jar")));
        assertEquals("target/no-such.jar: no such jar", e.getMessage());
    }

    @Test
    void comparesABuildLoadedInItsOwnClassLoader() throws Exception {
        Method main = CompareBuilds.mainOf(Path.of("target/classes"), libraryOf(CommandLine.class),
                libraryOf(Load.class));
        assertTrue(main.getDeclaringClass().getClassLoader() != CompareBuildsTest.class.getClassLoader(),
                "the build's classes come from a loader of their own");
        String[] bench = {"--scene", "scenes/bench/spec-example.yaml", "--width", "40", "--height", "30", "--spp", "1",
                "--threads", "1", "--bench", "3"};
        CompareBuilds.Result result = CompareBuilds.compare("spec-example", main, main, bench, 2);
        assertTrue(result.medianA() > 0 && result.medianB() > 0, result.line());
        assertTrue(result.ratioQ1() <= result.ratio() && result.ratio() <= result.ratioQ3(), result.line());
    }

    @Test
    void threeBuildsAreEachComparedWithTheFirst() throws Exception {
        Method main = CompareBuilds.mainOf(Path.of("target/classes"), libraryOf(CommandLine.class),
                libraryOf(Load.class));
        String[] bench = {"--scene", "scenes/bench/spec-example.yaml", "--width", "40", "--height", "30", "--spp", "1",
                "--threads", "1", "--bench", "3"};
        java.util.List<CompareBuilds.Result> results = CompareBuilds.compareAll("spec-example",
                java.util.List.of(main, main, main), bench, 2);
        assertEquals(2, results.size(), "B against A and C against A");
        assertEquals("spec-example B", results.get(0).scene());
        assertEquals("spec-example C", results.get(1).scene());
        assertEquals(results.get(0).medianA(), results.get(1).medianA(), "both against the same runs of A");
    }

    private static URL libraryOf(Class<?> c) {
        return c.getProtectionDomain().getCodeSource().getLocation();
    }
}
