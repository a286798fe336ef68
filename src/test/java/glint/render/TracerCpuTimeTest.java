package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import glint.image.FrameBuffer;
import glint.scenefile.SceneLoader;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The render threads' CPU time that {@code --bench} prints beside each frame's wall-clock time. */
class TracerCpuTimeTest {

    @Test
    void renderCpuGrowsWithEachFrameAndNeverExceedsTheThreadsTimesTheWallClock() throws Exception {
        RenderScene compiled = RenderScene.compile(SceneLoader.load(Path.of("scenes/bench/spec-example.yaml")),
                new RenderSettings(Shading.COOK_TORRANCE, 5, 1e-3, 1e-9));
        FrameBuffer frame = new FrameBuffer(160, 120);
        int threads = 2;
        try (Tracer tracer = new Tracer(threads)) {
            assumeTrue(tracer.renderCpuNanos() >= 0, "this JVM has no thread CPU clocks");
            assertEquals(0, tracer.renderCpuNanos(), "no frame rendered yet");
            long before = tracer.renderCpuNanos();
            for (int i = 0; i < 3; i++) {
                long start = System.nanoTime();
                tracer.render(compiled, frame, 4, 0, 8);
                long wall = System.nanoTime() - start;
                long cpu = tracer.renderCpuNanos() - before;
                assertTrue(cpu > 0, "frame " + i + ": the threads' CPU time did not grow");
                // each thread is measured within the frame: together they cannot exceed threads x its
                // wall-clock time (1 ms allowed for the two clocks' reading)
                assertTrue(cpu <= threads * wall + 1_000_000,
                        "frame " + i + ": " + cpu + " ns of CPU in " + wall + " ns on " + threads + " threads");
                before += cpu;
            }
        }
    }
}
