package glint.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.app.Main;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The path integrator against Whitted's: a --bench run read back, and a scene's line. */
class CompareIntegratorsTest {

    @Test
    void readsTheLeastRenderCpuAndTheRaysAFrame() {
        CompareIntegrators.Run run = CompareIntegrators.parse("""
                frame 1: 40.00 ms, render cpu 60.00 ms
                frame 2: 41.50 ms, render cpu 81.00 ms
                bench: frames=2 median_ms=40.75 p95_ms=41.50 rays_per_s=2000000
                """);
        assertEquals(81.0, run.cpuMillis());
        assertEquals(81_500, run.raysPerFrame(), 1e-9); // 2e6 rays a second over a 40.75 ms median frame
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> CompareIntegrators.parse("frame 1: 40.00 ms, render cpu 60.00 ms\n"));
        assertEquals("no bench summary in: frame 1: 40.00 ms, render cpu 60.00 ms", e.getMessage());
    }

    @Test
    void aScenesLineGivesEachIntegratorsCostASampleAndTheRatio() {
        CompareIntegrators.Run[][] runs = {
            {new CompareIntegrators.Run(10, 2000), new CompareIntegrators.Run(12, 2000), new CompareIntegrators.Run(11, 2000)},
            {new CompareIntegrators.Run(20, 5000), new CompareIntegrators.Run(30, 5000), new CompareIntegrators.Run(33, 5000)}};
        // ratios 2, 2.5, 3; medians 11 ms and 30 ms over 1000 samples: 11,000 and 30,000 ns a sample
        assertEquals("s: whitted 11.0 ms (11000 ns a sample, 0.18M rays a CPU second, 2.0 rays a sample);"
                + " path 30.0 ms (30000 ns a sample, 0.17M rays a CPU second, 5.0 rays a sample);"
                + " path/whitted 2.500 (quartiles 2.250-2.750)", CompareIntegrators.line("s", runs, 1000));
    }

    @Test
    void insideAMatteBallEveryPathBouncesToItsLastHitWithAShadowRayAtEach(@TempDir Path folder) throws Exception {
        Path scene = folder.resolve("inside.yaml");
        Files.writeString(scene, """
                camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 60}
                lights: [{type: point, position: [0, 0.5, 0], intensity: 1}]
                objects: [{type: sphere, center: [0, 0, 0], radius: 5, material: {type: matte}}]
                """);
        double[] rays = new double[2];
        String[] outputs = new String[2];
        String[] integrators = {"whitted", "path"};
        for (int i = 0; i < 2; i++) {
            StringWriter out = new StringWriter(), err = new StringWriter();
            int status = Main.run(new String[] {"--scene", scene.toString(), "--width", "40", "--height", "30", "--spp",
                "1", "--depth", "5", "--threads", "1", "--bench", "2", "--integrator", integrators[i]},
                    new PrintWriter(out, true), new PrintWriter(err, true));
            assertEquals(0, status, err.toString());
            rays[i] = CompareIntegrators.parse(out.toString()).raysPerFrame();
            outputs[i] = out.toString();
        }
        // Whitted: the camera ray and one shadow ray; the path: 5 hits, a shadow ray at each, 4 rays between
        assertEquals(2 * 40 * 30, rays[0], printingError(outputs[0], 2 * 40 * 30));
        assertEquals(10 * 40 * 30, rays[1], printingError(outputs[1], 10 * 40 * 30));
    }

    /**
     * How far the rays a frame read back from a bench's summary may be from their count, by the printing alone:
     * the rate is the count over the median frame's unrounded time, printed to a ray a second, and the median
     * is printed to two decimals (within 0.005 ms), so their product errs by at most rays x (0.005 / median) and half a ray a second
     * times the median.
     */
    private static double printingError(String benchOutput, double rays) {
        Matcher m = Pattern.compile("median_ms=([0-9.]+)").matcher(benchOutput);
        assertTrue(m.find(), benchOutput);
        double medianMillis = Double.parseDouble(m.group(1));
        return rays * 0.005 / (medianMillis - 0.005) + 0.5 * medianMillis / 1000;
    }
}
